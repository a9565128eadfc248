//! What an action is handed (spec §8, Decision 0.4 "ports and state"): `rtc`, the
//! component's side of one action — its ports by name (`rtc.target_velocity`), each with
//! `is_new()`, `read()` and `clear()` (an in-port) or `write(sample)` (an out-port); its parameters by name (`rtc.param("PGainL")`);
//! the tick's simulated time and period (`rtc.time`, `rtc.period`, `rtc.tm`, `rtc.index`).
//!
//! The ports are the component's own, lent to the action while it runs and taken back when
//! it returns: a handle kept past its action (in `this`, say) finds nothing and says so.

use std::cell::RefCell;
use std::rc::Rc;

use rhai::{Dynamic, Engine, EvalAltResult, Map};

use super::program::api_error;
use super::values::{ScriptSample, time_map, what};
use crate::rtc::{InPort, OutPort, PortView, Sample, Tick};

type Fallible<T> = Result<T, Box<EvalAltResult>>;

/// An in-port a script reads: any [`InPort<T>`] of a sample a script knows.
pub trait ScriptIn: core::fmt::Debug {
    /// The seed's name (`InCurrentWheelAngle`).
    fn name(&self) -> &'static str;
    /// Whether unread data arrived.
    fn is_new(&self) -> bool;
    /// The newest sample as a map, marked read; `None` before any arrived.
    fn read(&self) -> Option<Map>;
    /// The newest sample as a map, without marking it read.
    fn peek(&self) -> Option<Map>;
    /// Drops unread data (002 §5.2.3 (3): stale data dropped at activation).
    fn clear(&self);
    /// Its view, for the system's description.
    fn view(&self) -> PortView;
    /// The port itself (an `InPort<T>`), to connect.
    fn as_any(&self) -> &dyn core::any::Any;
    /// A copy, unconnected (a checkpoint).
    fn boxed_clone(&self) -> Box<dyn ScriptIn>;
}

impl<T: ScriptSample + Sample> ScriptIn for InPort<T> {
    fn name(&self) -> &'static str {
        InPort::name(self)
    }
    fn is_new(&self) -> bool {
        InPort::is_new(self)
    }
    fn read(&self) -> Option<Map> {
        InPort::read(self).map(|s| s.to_map())
    }
    fn peek(&self) -> Option<Map> {
        InPort::peek(self).map(|s| s.to_map())
    }
    fn clear(&self) {
        InPort::clear(self);
    }
    fn view(&self) -> PortView {
        InPort::view(self)
    }
    fn as_any(&self) -> &dyn core::any::Any {
        self
    }
    fn boxed_clone(&self) -> Box<dyn ScriptIn> {
        Box::new(self.clone())
    }
}

/// An out-port a script writes: any [`OutPort<T>`] of a sample a script knows.
pub trait ScriptOut: core::fmt::Debug {
    /// The seed's name (`Torque`).
    fn name(&self) -> &'static str;
    /// The IDL type's name.
    fn idl(&self) -> &'static str;
    /// Checks `sample` against the port's IDL type and writes it.
    fn write(&mut self, sample: &Map) -> Result<(), String>;
    /// The last sample written, as a map.
    fn last(&self) -> Option<Map>;
    /// Its view, for the system's description.
    fn view(&self) -> PortView;
    /// The port itself (an `OutPort<T>`), to connect.
    fn as_any_mut(&mut self) -> &mut dyn core::any::Any;
    /// Drops its connections (the wiring connects it again).
    fn disconnect_all(&mut self);
    /// A copy, unconnected (a checkpoint).
    fn boxed_clone(&self) -> Box<dyn ScriptOut>;
}

impl<T: ScriptSample + Sample> ScriptOut for OutPort<T> {
    fn name(&self) -> &'static str {
        OutPort::name(self)
    }
    fn idl(&self) -> &'static str {
        T::IDL
    }
    fn write(&mut self, sample: &Map) -> Result<(), String> {
        let value = T::from_map(sample)?;
        OutPort::write(self, value);
        Ok(())
    }
    fn last(&self) -> Option<Map> {
        OutPort::last(self).map(ScriptSample::to_map)
    }
    fn view(&self) -> PortView {
        OutPort::view(self)
    }
    fn as_any_mut(&mut self) -> &mut dyn core::any::Any {
        self
    }
    fn disconnect_all(&mut self) {
        OutPort::disconnect_all(self);
    }
    fn boxed_clone(&self) -> Box<dyn ScriptOut> {
        Box::new(self.clone())
    }
}

/// A port of the component as the script names it: snake case of the seed's name
/// (`InCurrentWheelAngle` → `in_current_wheel_angle`, `OutSimulatedPositionToInventGUI` →
/// `out_simulated_position_to_invent_gui`).
pub fn script_name(seed_name: &str) -> String {
    let chars: Vec<char> = seed_name.chars().collect();
    let mut out = String::with_capacity(seed_name.len() + 4);
    for (i, &c) in chars.iter().enumerate() {
        if c.is_ascii_uppercase() {
            let prev_lower = i > 0 && chars[i - 1].is_ascii_lowercase();
            let acronym_end = i > 0
                && chars[i - 1].is_ascii_uppercase()
                && chars.get(i + 1).is_some_and(char::is_ascii_lowercase);
            if prev_lower || acronym_end {
                out.push('_');
            }
            out.push(c.to_ascii_lowercase());
        } else {
            out.push(c);
        }
    }
    out
}

/// The component's side, lent to one action.
#[derive(Debug, Default)]
pub struct Io {
    /// The in-ports, with their script names.
    pub ins: Vec<(String, Box<dyn ScriptIn>)>,
    /// The out-ports, with their script names.
    pub outs: Vec<(String, Box<dyn ScriptOut>)>,
    /// The parameters' names and effective values (spec §1's reflection timing).
    pub params: Vec<(&'static str, f64, bool)>,
    /// The tick.
    pub tick: Tick,
    /// Whether the action that was handed it still runs.
    pub live: bool,
}

/// `rtc`: what one action is handed.
#[derive(Debug, Clone)]
pub struct Rtc(pub Rc<RefCell<Io>>);

/// One of the component's ports, as `rtc.<name>` gives it.
#[derive(Debug, Clone)]
pub struct Port {
    io: Rc<RefCell<Io>>,
    name: String,
    /// In-port `i`, or
    input: Option<usize>,
    /// out-port `o`.
    output: Option<usize>,
}

const STALE: &str = "is a handle from an earlier action: `rtc` and its ports are valid only \
                     during the action that received them (keep values in `this`)";

fn stale(name: &str) -> Box<EvalAltResult> {
    api_error(format!("`{name}` {STALE}"))
}

impl Rtc {
    fn get(&mut self, key: &str) -> Fallible<Dynamic> {
        let io = self.0.borrow();
        if !io.live {
            return Err(stale("rtc"));
        }
        let port = |input, output| Port {
            io: Rc::clone(&self.0),
            name: key.to_owned(),
            input,
            output,
        };
        if let Some(i) = io.ins.iter().position(|(n, _)| n == key) {
            return Ok(Dynamic::from(port(Some(i), None)));
        }
        if let Some(o) = io.outs.iter().position(|(n, _)| n == key) {
            return Ok(Dynamic::from(port(None, Some(o))));
        }
        match key {
            "time" => Ok(Dynamic::from_float(io.tick.seconds())),
            "period" => Ok(Dynamic::from_float(io.tick.period())),
            "tm" => Ok(time_map(io.tick.tm())),
            "index" => Ok(Dynamic::from_int(io.tick.index as i64)),
            _ => Err(api_error(format!(
                "the component has no port `{key}` (its in-ports: {}; its out-ports: {}; \
                 and rtc.time, rtc.period, rtc.tm, rtc.index, rtc.param(\"name\"))",
                names(io.ins.iter().map(|(n, _)| n)),
                names(io.outs.iter().map(|(n, _)| n)),
            ))),
        }
    }

    fn param(&mut self, name: &str) -> Fallible<Dynamic> {
        let io = self.0.borrow();
        if !io.live {
            return Err(stale("rtc"));
        }
        match io.params.iter().find(|(n, ..)| *n == name) {
            Some(&(_, v, true)) => Ok(Dynamic::from_int(v as i64)),
            Some(&(_, v, false)) => Ok(Dynamic::from_float(v)),
            None => Err(api_error(format!(
                "the component has no parameter `{name}` (its parameters: {})",
                names(io.params.iter().map(|(n, ..)| n))
            ))),
        }
    }
}

fn names<S: AsRef<str>>(names: impl Iterator<Item = S>) -> String {
    let all: Vec<String> = names.map(|n| n.as_ref().to_owned()).collect();
    if all.is_empty() {
        "none".to_owned()
    } else {
        all.join(", ")
    }
}

impl Port {
    fn is_new(&mut self) -> Fallible<bool> {
        let io = self.io()?;
        match self.input {
            Some(i) => Ok(io.ins[i].1.is_new()),
            None => Err(api_error(format!(
                "`is_new()` on `{}`, an out-port: out-ports are written, not read",
                self.name
            ))),
        }
    }

    fn read(&mut self) -> Fallible<Dynamic> {
        let io = self.io()?;
        match self.input {
            Some(i) => io.ins[i].1.read().map(Dynamic::from_map).ok_or_else(|| {
                api_error(format!(
                    "`read()` on `{}`, which has no data yet (ask `is_new()` first)",
                    self.name
                ))
            }),
            None => Err(api_error(format!(
                "`read()` on `{}`, an out-port: out-ports are written, not read",
                self.name
            ))),
        }
    }

    fn clear(&mut self) -> Fallible<()> {
        let io = self.io()?;
        match self.input {
            Some(i) => {
                io.ins[i].1.clear();
                Ok(())
            }
            None => Err(api_error(format!(
                "`clear()` on `{}`, an out-port: only an in-port holds data to drop",
                self.name
            ))),
        }
    }

    fn write(&mut self, sample: Dynamic) -> Fallible<()> {
        let name = self.name.clone();
        let output = self.output;
        let mut io = self.io_mut()?;
        let Some(o) = output else {
            return Err(api_error(format!(
                "`write()` on `{name}`, an in-port: in-ports are read, not written"
            )));
        };
        let port = &mut io.outs[o].1;
        let idl = port.idl();
        let Some(map) = sample.read_lock::<Map>() else {
            return Err(api_error(format!(
                "`write()` on `{name}` takes a {idl} as a map #{{…}}, not {}",
                what(&sample)
            )));
        };
        port.write(&map)
            .map_err(|e| api_error(format!("`write()` on `{name}` ({idl}): {e}")))
    }

    fn io(&self) -> Fallible<std::cell::Ref<'_, Io>> {
        let io = self.io.borrow();
        if io.live {
            Ok(io)
        } else {
            Err(stale(&self.name))
        }
    }

    fn io_mut(&self) -> Fallible<std::cell::RefMut<'_, Io>> {
        let io = self.io.borrow_mut();
        if io.live {
            Ok(io)
        } else {
            Err(stale(&self.name))
        }
    }
}

/// Registers `rtc`'s and the ports' functions in `engine`.
pub fn register(engine: &mut Engine) {
    engine
        .register_type_with_name::<Rtc>("Rtc")
        .register_indexer_get(|rtc: &mut Rtc, key: &str| rtc.get(key))
        .register_fn("param", |rtc: &mut Rtc, name: &str| rtc.param(name))
        .register_type_with_name::<Port>("Port")
        .register_fn("is_new", Port::is_new)
        .register_fn("read", Port::read)
        .register_fn("clear", Port::clear)
        .register_fn("write", Port::write);
}
