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

//!
//! Without the feature `script` (the page's first download) there is no engine: a script is
//! refused when it is compiled, saying so, and the console and the errors are all that is
//! left of this module.

#[cfg(not(feature = "script"))]
mod absent;
mod console;
#[cfg(feature = "script")]
pub mod engine;
mod error;
#[cfg(feature = "script")]
mod io;
#[cfg(feature = "script")]
mod program;
#[cfg(feature = "script")]
mod values;

#[cfg(not(feature = "script"))]
pub use absent::Program;
pub use console::{CONSOLE_LINES, Console, ConsoleKind, ConsoleLine, LINE_CHARS};
pub use error::ScriptError;
#[cfg(feature = "script")]
pub use io::{Io, Rtc, ScriptIn, ScriptOut, script_name};
#[cfg(feature = "script")]
pub use program::{ACTIONS, DECLARATION, Program};
#[cfg(feature = "script")]
pub use values::ScriptSample;
