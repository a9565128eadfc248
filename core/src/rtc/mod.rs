//! The OpenRTM-style component model (spec §1, seed 003): lifecycle, execution context,
//! data ports (and what they show of themselves), IDL types and configuration.

mod error;
pub use error::{ConfigError, LifecycleError, TimestampError};

mod component;
mod conf_file;
mod config;
mod execution_context;
mod idl;
mod port;
mod rate;
mod sample;
mod state;

pub use component::{Component, ComponentError, ReturnCode, Tick};
pub use conf_file::{ConfEntry, ConfFile, ConfKey, without_bom};
pub use config::{
    ConfigAccess, Configuration, DEFAULT_SET, ParamKind, ParamSpec, ParamType, ParameterSet,
    Reflection,
};
pub use execution_context::{ComponentId, ExecutionContext, InputInjection, LifecycleEvent};
pub use idl::{Time, TimedDouble, TimedDoubleSeq, TimedPosition, TimedVelocity};
pub use port::{Connector, InPort, OutPort};
pub use rate::{MAX_BASE_RATE_HZ, period_ticks};
pub use sample::{PortDirection, PortView, Sample, SampleView, short, short_list};
pub use state::{ContextState, LifecycleState, Request};
