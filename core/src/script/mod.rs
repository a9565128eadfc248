//! Components a student writes (spec §8, Decisions 0.4): a script, in Rhai, whose functions
//! are the actions of seed 003, run by [`ScriptComponent`](crate::components::ScriptComponent)
//! in the place of one of the system's components.
//!
//! - [`engine`]: the sandboxed engine, its bounds and its math (`libm`);
//! - [`Program`]: a compiled script, its actions and its declaration, and the call of one
//!   action under the bounds;
//! - `io`: what an action is handed, `rtc` — the component's ports, parameters and tick;
//! - `values`: the IDL samples as maps of their fields;
//! - [`Console`]: what the script prints and its errors, bounded, repeats folded;
//! - [`ScriptError`]: what goes wrong, at its action, line and column.

mod console;
pub mod engine;
mod error;
mod io;
mod program;
mod values;

pub use console::{CONSOLE_LINES, Console, ConsoleKind, ConsoleLine, LINE_CHARS};
pub use error::ScriptError;
pub use io::{Io, Rtc, ScriptIn, ScriptOut, script_name};
pub use program::{ACTIONS, DECLARATION, Program};
pub use values::ScriptSample;
