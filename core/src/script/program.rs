//! A compiled script (spec §8, Decision 0.4 "loading"): its syntax checked, its actions
//! found, its declaration read; and the call of one action under the engine's bounds, with
//! whatever goes wrong said in the student's terms, at its line and column.

use std::cell::RefCell;
use std::collections::BTreeMap;
use std::rc::Rc;

use rhai::{AST, CallFnOptions, Dynamic, Engine, EvalAltResult, ImmutableString, Position, Scope};

use super::engine::{self, CALL_DEPTH, OPERATIONS};
use super::error::ScriptError;
use super::io::{self, Rtc};
use crate::present::excerpt_of;

/// The actions of seed 003's table, as a script names them (snake case).
pub const ACTIONS: [&str; 12] = [
    "on_initialize",
    "on_finalize",
    "on_startup",
    "on_shutdown",
    "on_activated",
    "on_deactivated",
    "on_execute",
    "on_state_update",
    "on_aborting",
    "on_error",
    "on_reset",
    "on_rate_changed",
];

/// The script's declaration of the component it stands in for:
/// `const COMPONENT = "MotorControl";` at its top level.
pub const DECLARATION: &str = "COMPONENT";

/// The most characters of an error's words: a script's own text (a name, a thrown value)
/// can be any size, and the error quotes it.
pub const MESSAGE_CHARS: usize = 1_000;

/// Lines one action may `print` (the rest are dropped, and the console says so).
const PRINTS_PER_ACTION: usize = 100;

/// A failure inside a native function of the component's (a port, a sample, a parameter),
/// told apart from what the script itself throws.
#[derive(Debug, Clone)]
pub struct ApiError(pub String);

/// `message` as the error a native function of the component's returns.
pub fn api_error(message: String) -> Box<EvalAltResult> {
    Box::new(EvalAltResult::ErrorRuntime(
        Dynamic::from(ApiError(message)),
        Position::NONE,
    ))
}

/// A compiled script: shared by the copies of its component (a checkpoint copies the
/// component, not the program).
#[derive(Clone)]
pub struct Program {
    engine: Rc<Engine>,
    /// The same engine with a debugger that notes the place of every step, made when an
    /// action first runs past a bound: the engine says where a bound ran out only as the
    /// action's call, so the action is run again on a copy to find the place.
    locator: Rc<std::cell::OnceCell<Locator>>,
    ast: Rc<AST>,
    printed: Rc<RefCell<Vec<String>>>,
    source: Rc<str>,
    name: Rc<str>,
    declared: Option<String>,
    /// Each defined action and whether it takes `rtc`.
    actions: BTreeMap<&'static str, bool>,
}

impl core::fmt::Debug for Program {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("Program")
            .field("name", &self.name)
            .field("declared", &self.declared)
            .field("actions", &self.actions)
            .finish()
    }
}

impl PartialEq for Program {
    fn eq(&self, other: &Self) -> bool {
        self.source == other.source && self.name == other.name
    }
}

impl Program {
    /// Compiles `source` (named `name`, a file name for people) and runs its top level once
    /// (constants, the declaration) under the bounds. A syntax error, an action defined with
    /// more than one parameter, or a failing top level refuses it.
    pub fn compile(name: &str, source: &str) -> Result<Self, ScriptError> {
        let printed = Rc::new(RefCell::new(Vec::new()));
        let mut engine = engine::engine();
        io::register(&mut engine);
        let sink = Rc::clone(&printed);
        engine.on_print(move |text| {
            let mut lines = sink.borrow_mut();
            if lines.len() <= PRINTS_PER_ACTION {
                lines.push(text.to_owned());
            }
        });
        let sink = Rc::clone(&printed);
        engine.on_debug(move |text, _, _| {
            let mut lines = sink.borrow_mut();
            if lines.len() <= PRINTS_PER_ACTION {
                lines.push(text.to_owned());
            }
        });
        let ast = engine.compile(source).map_err(|e| {
            let (line, column) = place(e.position());
            let message = match e.err_type() {
                rhai::ParseErrorType::VariableUndefined(name) => format!(
                    "`{name}` is not defined here: a function sees only its parameters, its own \
                     `let`s and `this` (a `const` of the top level is not seen inside a \
                     function: write a function that returns it)"
                ),
                other => other.to_string(),
            };
            ScriptError::Syntax {
                line,
                column,
                message: excerpt_of(&message, MESSAGE_CHARS),
            }
        })?;
        let mut actions = BTreeMap::new();
        for f in ast.iter_functions() {
            let Some(&action) = ACTIONS.iter().find(|a| **a == f.name) else {
                continue;
            };
            if f.params.len() > 1 {
                return Err(ScriptError::Signature {
                    action: action.to_owned(),
                    line: 0,
                    message: format!(
                        "an action takes one parameter, `rtc` (or none); this one takes {}",
                        f.params.len()
                    ),
                });
            }
            actions.insert(action, f.params.len() == 1);
        }
        let mut scope = Scope::new();
        engine
            .run_ast_with_scope(&mut scope, &ast)
            .map_err(|e| convert("top level", *e))?;
        let declared = scope
            .get_value::<ImmutableString>(DECLARATION)
            .map(|s| s.to_string());
        printed.borrow_mut().clear();
        Ok(Self {
            engine: Rc::new(engine),
            locator: Rc::default(),
            ast: Rc::new(ast),
            printed,
            source: source.into(),
            name: name.into(),
            declared,
            actions,
        })
    }

    /// The script's text.
    pub fn source(&self) -> &str {
        &self.source
    }

    /// Its name (a file name).
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The component its declaration names (`const COMPONENT = "…";`), if it has one.
    pub fn declared(&self) -> Option<&str> {
        self.declared.as_deref()
    }

    /// Whether it defines `action`.
    pub fn defines(&self, action: &str) -> bool {
        self.actions.contains_key(action)
    }

    /// The actions it defines.
    pub fn actions(&self) -> impl Iterator<Item = &'static str> + '_ {
        self.actions.keys().copied()
    }

    /// Runs `action` with `this` bound to `state` and `rtc` as its argument. Returns what it
    /// printed; on a failure, the error and what it printed before. An action the script
    /// does not define succeeds and does nothing.
    pub fn call(
        &self,
        action: &'static str,
        state: &mut Dynamic,
        rtc: Rtc,
    ) -> (Vec<String>, Result<(), ScriptError>) {
        let Some(&takes_rtc) = self.actions.get(action) else {
            return (Vec::new(), Ok(()));
        };
        let mut scope = Scope::new();
        let options = CallFnOptions::new()
            .eval_ast(false)
            .rewind_scope(true)
            .bind_this_ptr(state);
        let result = if takes_rtc {
            self.engine.call_fn_with_options::<Dynamic>(
                options,
                &mut scope,
                &self.ast,
                action,
                (rtc,),
            )
        } else {
            self.engine
                .call_fn_with_options::<Dynamic>(options, &mut scope, &self.ast, action, ())
        };
        let printed = core::mem::take(&mut *self.printed.borrow_mut());
        (printed, result.map(drop).map_err(|e| convert(action, *e)))
    }

    /// Where `action` runs past a bound, run on copies (`state`, and `rtc` over copies of
    /// the ports): the last place the engine stepped through, 1-based.
    pub fn locate(
        &self,
        action: &'static str,
        state: &mut Dynamic,
        rtc: Rtc,
    ) -> Option<(usize, usize)> {
        let takes_rtc = *self.actions.get(action)?;
        let locator = self.locator.get_or_init(Locator::new);
        locator.last.set(Position::NONE);
        let mut scope = Scope::new();
        let options = CallFnOptions::new()
            .eval_ast(false)
            .rewind_scope(true)
            .bind_this_ptr(state);
        let engine = &locator.engine;
        let _ = if takes_rtc {
            engine.call_fn_with_options::<Dynamic>(options, &mut scope, &self.ast, action, (rtc,))
        } else {
            engine.call_fn_with_options::<Dynamic>(options, &mut scope, &self.ast, action, ())
        };
        let (line, column) = place(locator.last.get());
        (line > 0).then_some((line, column))
    }
}

/// An engine that notes the place of every step it takes ([`Program::locate`]).
struct Locator {
    engine: Engine,
    last: Rc<std::cell::Cell<Position>>,
}

impl Locator {
    fn new() -> Self {
        let last = Rc::new(std::cell::Cell::new(Position::NONE));
        let mut engine = engine::engine();
        io::register(&mut engine);
        let seen = Rc::clone(&last);
        #[allow(deprecated)] // "not deprecated, but volatile" (rhai's words)
        engine.register_debugger(
            |_, debugger| debugger,
            move |_, event, _, _, pos| {
                if matches!(event, rhai::debugger::DebuggerEvent::Step) && !pos.is_none() {
                    seen.set(pos);
                }
                Ok(rhai::debugger::DebuggerCommand::StepInto)
            },
        );
        Self { engine, last }
    }
}

/// A position as `(line, column)`, 1-based; `(0, 0)` where there is none.
fn place(pos: Position) -> (usize, usize) {
    (pos.line().unwrap_or(0), pos.position().unwrap_or(0))
}

/// An engine error as the student reads it: the innermost failure, where it happened.
fn convert(action: &str, error: EvalAltResult) -> ScriptError {
    use EvalAltResult as E;
    let mut error = error;
    let mut outer = Position::NONE;
    let mut helper: Option<String> = None;
    while let E::ErrorInFunctionCall(name, _, inner, pos) = error {
        if name != action {
            helper = Some(name);
        }
        if !pos.is_none() {
            outer = pos;
        }
        error = *inner;
    }
    let pos = match error.position() {
        p if p.is_none() => outer,
        p => p,
    };
    let (line, column) = place(pos);
    let within = helper.map(|h| format!(" (in `{h}`)")).unwrap_or_default();
    let action = action.to_owned();
    let bound = |message: String| ScriptError::Bound {
        action: action.clone(),
        line,
        column,
        message: excerpt_of(&format!("{message}{within}"), MESSAGE_CHARS),
    };
    let message = match &error {
        E::ErrorTooManyOperations(_) => {
            return bound(format!(
                "ran past its budget of {OPERATIONS} operations — an endless loop? Every \
                 action must end within its budget"
            ));
        }
        E::ErrorStackOverflow(_) => {
            return bound(format!(
                "called functions more than {CALL_DEPTH} deep — endless recursion?"
            ));
        }
        E::ErrorDataTooLarge(what, _) => {
            return bound(format!(
                "{what} grew past its bound ({} bytes for a string, {} items for an \
                 array, {} entries for a map)",
                engine::STRING_BYTES,
                engine::ARRAY_ITEMS,
                engine::MAP_ENTRIES
            ));
        }
        E::ErrorTooManyVariables(_) => {
            return bound("made more variables than an action may hold".to_owned());
        }
        E::ErrorRuntime(value, _) => match value.clone().try_cast::<ApiError>() {
            Some(ApiError(m)) => m,
            None => format!("the script threw {value}"),
        },
        E::ErrorVariableNotFound(name, _) => format!(
            "`{name}` is not defined here (a value kept between actions lives in `this`, \
             e.g. `this.{name}`)"
        ),
        E::ErrorFunctionNotFound(sig, _) => format!("there is no function `{sig}`"),
        E::ErrorPropertyNotFound(name, _) => format!("there is no property `{name}` here"),
        E::ErrorIndexNotFound(index, _) => format!("there is no `{index}` here"),
        E::ErrorMismatchDataType(expected, actual, _) => {
            format!("expected {expected}, but got {actual}")
        }
        E::ErrorMismatchOutputType(expected, actual, _) => {
            format!("expected {expected}, but got {actual}")
        }
        E::ErrorArrayBounds(len, index, _) => {
            format!("index {index} is outside the array, which has {len} items")
        }
        E::ErrorStringBounds(len, index, _) => {
            format!("index {index} is outside the string, which has {len} characters")
        }
        E::ErrorArithmetic(m, _) => format!("arithmetic: {m}"),
        E::ErrorUnboundThis(_) => {
            "`this` (the component's state) is used outside an action".to_owned()
        }
        E::ErrorAssignmentToConstant(name, _) => format!("`{name}` is a constant"),
        E::ErrorFor(_) => "`for` needs something to go through (an array, a range)".to_owned(),
        other => {
            let text = other.to_string();
            // The engine's own words end with the place, which is said apart.
            match text.rfind(" (line ") {
                Some(i) => text[..i].to_owned(),
                None => text,
            }
        }
    };
    ScriptError::Runtime {
        action,
        line,
        column,
        message: excerpt_of(&format!("{message}{within}"), MESSAGE_CHARS),
    }
}
