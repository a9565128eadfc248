//! Configuration parameters (spec §1 "Configuration parameters", 000 §4, 002 §4).
//!
//! A component declares its parameters once with
//! [`define_parameters!`](crate::define_parameters): a plain struct the component reads with
//! ordinary field access, plus a table of [`ParamSpec`] (the seed's name, unit, default, range
//! and reflection timing). [`Configuration`] holds two copies:
//! - *requested*: what the user set (RT System Editor's ConfigurationView, a `.conf` file);
//! - *effective*: what the component reads. An `always` parameter is copied at once; an
//!   `on_activation` one when the component is activated (002 §5.2.3 (2)), so until then it
//!   shows as *pending*.

use std::collections::BTreeMap;
use std::fmt;

use serde::{Deserialize, Serialize};

use super::conf_file::{ConfFile, ConfKey};
use crate::errors::ConfigError;
use crate::present::excerpt;

/// When a changed value reaches the component (000/002 §4.2 "反映タイミング").
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
pub enum Reflection {
    /// 常時: at the next tick.
    Always,
    /// 初期化時: copied when the component is activated (just before `on_activated`), then
    /// locked until the next activation.
    OnActivation,
}

impl fmt::Display for Reflection {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::Always => "always",
            Self::OnActivation => "on_activation",
        })
    }
}

/// A parameter's type as the seed's table gives it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
pub enum ParamKind {
    /// `double`.
    Double,
    /// `int` (stored as a whole number).
    Int,
}

impl ParamKind {
    /// The seed's type name.
    pub fn name(self) -> &'static str {
        match self {
            Self::Double => "double",
            Self::Int => "int",
        }
    }
}

/// One parameter's declaration.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ParamSpec {
    /// The seed's name, e.g. `RouteRemakeDistance`.
    pub name: &'static str,
    /// Its type.
    pub kind: ParamKind,
    /// Unit, e.g. `m`, `%`, `rad`, or `-`.
    pub unit: &'static str,
    /// Default value.
    pub default: f64,
    /// Smallest allowed value (inclusive); `-inf` for none.
    pub min: f64,
    /// Largest allowed value (inclusive); `+inf` for none.
    pub max: f64,
    /// When a change takes effect.
    pub reflection: Reflection,
    /// What it means, in English.
    pub description: &'static str,
    /// The seed's own words for it (its 説明 column, Japanese), for the parameters the seeds
    /// describe (000 and 002 §4.2); `None` for the components the seeds do not describe.
    pub seed_text: Option<&'static str>,
}

impl ParamSpec {
    /// The range as text, e.g. `[0, 100]` or `[0, ∞)`.
    pub fn range_text(&self) -> String {
        let lo = if self.min.is_finite() {
            format!("[{}", self.min)
        } else {
            "(-∞".to_owned()
        };
        let hi = if self.max.is_finite() {
            format!("{}]", self.max)
        } else {
            "∞)".to_owned()
        };
        format!("{lo}, {hi}")
    }

    /// Checks `value` against type and range. NaN and ±∞ are refused as out of range (every
    /// range is finite or open at its infinite ends).
    pub fn check(&self, value: f64, line: Option<usize>) -> Result<f64, ConfigError> {
        if self.kind == ParamKind::Int && value.is_finite() && value.fract() != 0.0 {
            return Err(ConfigError::BadValue {
                name: self.name.to_owned(),
                value: value.to_string(),
                kind: self.kind.name(),
                line,
            });
        }
        if !value.is_finite() || value < self.min || value > self.max {
            return Err(ConfigError::OutOfRange {
                name: self.name.to_owned(),
                value: value.to_string(),
                range: self.range_text(),
                line,
            });
        }
        Ok(value)
    }

    /// Parses `text` as this parameter's type and checks its range.
    pub fn parse(&self, text: &str, line: Option<usize>) -> Result<f64, ConfigError> {
        let t = text.trim();
        let bad = || ConfigError::BadValue {
            name: self.name.to_owned(),
            value: excerpt(t),
            kind: self.kind.name(),
            line,
        };
        let v = match self.kind {
            ParamKind::Double => t.parse::<f64>().map_err(|_| bad())?,
            ParamKind::Int => t.parse::<i64>().map_err(|_| bad())? as f64,
        };
        self.check(v, line)
    }

    /// Formats a value as a `.conf` file writes it.
    pub fn format(&self, value: f64) -> String {
        match self.kind {
            ParamKind::Int => format!("{}", value as i64),
            ParamKind::Double if value.fract() == 0.0 && value.abs() < 1e15 => {
                format!("{value:.1}")
            }
            ParamKind::Double => format!("{value}"),
        }
    }
}

/// A field type usable in [`define_parameters!`](crate::define_parameters).
pub trait ParamType: Copy {
    /// The kind recorded in the spec.
    const KIND: ParamKind;
    /// To the common representation.
    fn to_f64(self) -> f64;
    /// From the common representation (already checked by [`ParamSpec::check`]).
    fn from_f64(v: f64) -> Self;
}

impl ParamType for f64 {
    const KIND: ParamKind = ParamKind::Double;
    fn to_f64(self) -> f64 {
        self
    }
    fn from_f64(v: f64) -> Self {
        v
    }
}

impl ParamType for i32 {
    const KIND: ParamKind = ParamKind::Int;
    fn to_f64(self) -> f64 {
        f64::from(self)
    }
    fn from_f64(v: f64) -> Self {
        v as i32
    }
}

/// A component's parameter struct; implemented by [`define_parameters!`](crate::define_parameters).
pub trait ParameterSet: Clone + PartialEq + fmt::Debug + 'static {
    /// The declarations, in the seed's table order.
    const SPECS: &'static [ParamSpec];
    /// The value of parameter `index` (an index into `SPECS`).
    fn get(&self, index: usize) -> f64;
    /// Sets parameter `index` (already checked).
    fn put(&mut self, index: usize, value: f64);
    /// Every parameter at its default.
    fn defaults() -> Self;
}

/// Declares a parameter struct and its [`ParameterSet`] table.
///
/// Each field is `name: type = (seed name, unit, default, min, max, reflection, description)`
/// with `type` `f64` or `i32` and `reflection` `Always` or `OnActivation`; the description is
/// English, optionally followed by `seed: "…"`, the seed's own (Japanese) text for it. The struct derives
/// serde's `Serialize` / `Deserialize`, so the calling crate needs `serde` (with `derive`).
///
/// ```
/// rtnav::define_parameters! {
///     /// Example.
///     pub struct ExampleParams {
///         /// Gain.
///         p_gain: f64 = ("PGain", "-", 5.0, 0.0, f64::INFINITY, Always, "P gain"),
///         /// Wheel id.
///         wheel_id: i32 = ("wheelID", "-", 0.0, 0.0, 16.0, OnActivation, "wheel id"),
///     }
/// }
/// let p = <ExampleParams as rtnav::rtc::ParameterSet>::defaults();
/// assert_eq!(p.p_gain, 5.0);
/// ```
#[macro_export]
macro_rules! define_parameters {
    (@seed) => { None };
    (@seed $seed:expr) => { Some($seed) };
    (
        $(#[$meta:meta])*
        pub struct $name:ident {
            $(
                $(#[$fmeta:meta])*
                $field:ident : $ty:ty = ($pname:expr, $unit:expr, $default:expr, $min:expr, $max:expr, $refl:ident, $desc:expr $(, seed: $seed:expr)?)
            ),* $(,)?
        }
    ) => {
        $(#[$meta])*
        #[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
        pub struct $name {
            $( $(#[$fmeta])* pub $field: $ty, )*
        }

        impl $crate::rtc::ParameterSet for $name {
            const SPECS: &'static [$crate::rtc::ParamSpec] = &[
                $( $crate::rtc::ParamSpec {
                    name: $pname,
                    kind: <$ty as $crate::rtc::ParamType>::KIND,
                    unit: $unit,
                    default: $default,
                    min: $min,
                    max: $max,
                    reflection: $crate::rtc::Reflection::$refl,
                    description: $desc,
                    seed_text: $crate::define_parameters!(@seed $($seed)?),
                }, )*
            ];
            #[allow(unused_assignments)]
            fn get(&self, index: usize) -> f64 {
                let mut i = 0usize;
                $( if index == i { return <$ty as $crate::rtc::ParamType>::to_f64(self.$field); } i += 1; )*
                f64::NAN
            }
            #[allow(unused_assignments)]
            fn put(&mut self, index: usize, value: f64) {
                let mut i = 0usize;
                $( if index == i { self.$field = <$ty as $crate::rtc::ParamType>::from_f64(value); return; } i += 1; )*
            }
            fn defaults() -> Self {
                Self { $( $field: <$ty as $crate::rtc::ParamType>::from_f64($default), )* }
            }
        }

        impl Default for $name {
            fn default() -> Self {
                <Self as $crate::rtc::ParameterSet>::defaults()
            }
        }
    };
}

/// The name of the configuration set every component has.
pub const DEFAULT_SET: &str = "default";

/// A component's configuration: requested and effective values, and named sets.
///
/// **Decision (configuration sets)**: every set holds a value for every parameter. A set a
/// `.conf` file creates starts as a copy of the `default` set (after that file's `default`
/// lines) and then takes the values the file names for it, so switching sets never depends on
/// which set was active before. Setting a parameter changes the active set (as OpenRTM's
/// ConfigurationView does).
#[derive(Debug, Clone, PartialEq)]
pub struct Configuration<P: ParameterSet> {
    /// The active set's values; always equal to `sets[active_set]`.
    requested: P,
    effective: P,
    sets: BTreeMap<String, P>,
    active_set: String,
    /// `conf.__widget__.NAME` entries as read, kept for the GUI.
    widgets: BTreeMap<usize, String>,
}

impl<P: ParameterSet> Default for Configuration<P> {
    fn default() -> Self {
        Self::new()
    }
}

impl<P: ParameterSet> Configuration<P> {
    /// Every parameter at its default, in the set `default`.
    pub fn new() -> Self {
        let mut sets = BTreeMap::new();
        sets.insert(DEFAULT_SET.to_owned(), P::defaults());
        Self {
            requested: P::defaults(),
            effective: P::defaults(),
            sets,
            active_set: DEFAULT_SET.to_owned(),
            widgets: BTreeMap::new(),
        }
    }

    /// What the component reads.
    pub fn params(&self) -> &P {
        &self.effective
    }

    /// What the user set (equals [`Configuration::params`] except for pending
    /// `on_activation` parameters).
    pub fn requested(&self) -> &P {
        &self.requested
    }

    /// The values of configuration set `name`, if it exists.
    pub fn set_values(&self, name: &str) -> Option<&P> {
        self.sets.get(name)
    }

    fn index(name: &str, line: Option<usize>) -> Result<usize, ConfigError> {
        P::SPECS
            .iter()
            .position(|s| s.name == name)
            .ok_or_else(|| ConfigError::UnknownParameter {
                name: excerpt(name),
                line,
            })
    }

    /// Makes `values` the requested values; `always` parameters take effect at once.
    fn request(&mut self, values: P) {
        for (i, spec) in P::SPECS.iter().enumerate() {
            if spec.reflection == Reflection::Always {
                self.effective.put(i, values.get(i));
            }
        }
        self.sets.insert(self.active_set.clone(), values.clone());
        self.requested = values;
    }

    fn set_index(&mut self, i: usize, value: f64) {
        let mut values = self.requested.clone();
        values.put(i, value);
        self.request(values);
    }
}

/// Object-safe access to any component's configuration, for the execution context, the GUI
/// and `.conf` files.
pub trait ConfigAccess {
    /// A copy to try changes on (all of them are checked before any is made).
    fn boxed_copy(&self) -> Box<dyn ConfigAccess>;
    /// The parameter declarations.
    fn specs(&self) -> &'static [ParamSpec];
    /// The requested value of `name`.
    fn value(&self, name: &str) -> Result<f64, ConfigError>;
    /// The value the component is using now.
    fn effective_value(&self, name: &str) -> Result<f64, ConfigError>;
    /// Whether `name` has a requested value that waits for the next activation.
    fn is_pending(&self, name: &str) -> Result<bool, ConfigError>;
    /// Sets `name` in the active set; an `always` parameter takes effect at once, an
    /// `on_activation` one is pending until the next activation. An unknown name or an
    /// out-of-range value is refused and nothing changes.
    fn set(&mut self, name: &str, value: f64) -> Result<(), ConfigError>;
    /// Parses and sets `name` from text.
    fn set_text(&mut self, name: &str, text: &str) -> Result<(), ConfigError>;
    /// Copies every requested value to the effective values (the context calls this just
    /// before `on_activated`).
    fn apply_on_activation(&mut self);
    /// The effective values, in declaration order (kept by the context across an
    /// activation, to put back if it fails).
    fn effective_values(&self) -> Vec<f64>;
    /// Puts back effective values taken by [`ConfigAccess::effective_values`]: an activation
    /// that failed leaves the old values in effect (spec §1 Decision 0.2). The requested
    /// values stay, pending until the next activation.
    fn restore_effective(&mut self, values: &[f64]);
    /// The names of the configuration sets.
    fn set_names(&self) -> Vec<String>;
    /// The active configuration set.
    fn active_set(&self) -> &str;
    /// Makes `name` the active set and requests its values (atomically; `on_activation`
    /// parameters stay pending until the next activation).
    fn activate_set(&mut self, name: &str) -> Result<(), ConfigError>;
    /// Applies a parsed `.conf` file: every set it names is created or updated, the active
    /// set's values applied. Atomic: on any error nothing changes.
    fn load_conf(&mut self, conf: &ConfFile) -> Result<(), ConfigError>;
    /// Writes every set as an OpenRTM `.conf` file.
    fn to_conf(&self) -> String;
}

impl<P: ParameterSet> ConfigAccess for Configuration<P> {
    fn boxed_copy(&self) -> Box<dyn ConfigAccess> {
        Box::new(self.clone())
    }

    fn specs(&self) -> &'static [ParamSpec] {
        P::SPECS
    }

    fn value(&self, name: &str) -> Result<f64, ConfigError> {
        Ok(self.requested.get(Self::index(name, None)?))
    }

    fn effective_value(&self, name: &str) -> Result<f64, ConfigError> {
        Ok(self.effective.get(Self::index(name, None)?))
    }

    fn is_pending(&self, name: &str) -> Result<bool, ConfigError> {
        let i = Self::index(name, None)?;
        Ok(self.requested.get(i).to_bits() != self.effective.get(i).to_bits())
    }

    fn set(&mut self, name: &str, value: f64) -> Result<(), ConfigError> {
        let i = Self::index(name, None)?;
        let v = P::SPECS[i].check(value, None)?;
        self.set_index(i, v);
        Ok(())
    }

    fn set_text(&mut self, name: &str, text: &str) -> Result<(), ConfigError> {
        let i = Self::index(name, None)?;
        let v = P::SPECS[i].parse(text, None)?;
        self.set_index(i, v);
        Ok(())
    }

    fn apply_on_activation(&mut self) {
        self.effective = self.requested.clone();
    }

    fn effective_values(&self) -> Vec<f64> {
        (0..P::SPECS.len()).map(|i| self.effective.get(i)).collect()
    }

    fn restore_effective(&mut self, values: &[f64]) {
        for (i, &v) in values.iter().enumerate().take(P::SPECS.len()) {
            self.effective.put(i, v);
        }
    }

    fn set_names(&self) -> Vec<String> {
        self.sets.keys().cloned().collect()
    }

    fn active_set(&self) -> &str {
        &self.active_set
    }

    fn activate_set(&mut self, name: &str) -> Result<(), ConfigError> {
        let values = self
            .sets
            .get(name)
            .cloned()
            .ok_or_else(|| ConfigError::UnknownSet {
                name: excerpt(name),
            })?;
        self.active_set = name.to_owned();
        self.request(values);
        Ok(())
    }

    fn load_conf(&mut self, conf: &ConfFile) -> Result<(), ConfigError> {
        let mut next = self.clone();
        let mut active = None;
        // The values each set names, in file order (checked before anything is applied).
        let mut named: BTreeMap<&str, Vec<(usize, f64)>> = BTreeMap::new();
        for e in &conf.entries {
            // An unknown parameter is named by the whole key, as written in the file.
            let index = |name: &str| {
                Self::index(name, Some(e.line)).map_err(|_| ConfigError::UnknownParameter {
                    name: excerpt(&e.key.to_string()),
                    line: Some(e.line),
                })
            };
            match &e.key {
                ConfKey::Param { set, name } => {
                    let i = index(name)?;
                    let v = P::SPECS[i].parse(&e.value, Some(e.line))?;
                    named.entry(set.as_str()).or_default().push((i, v));
                }
                ConfKey::Widget { name } => {
                    let i = index(name)?;
                    next.widgets.insert(i, e.value.clone());
                }
                ConfKey::Meta { name, .. } => {
                    index(name)?;
                }
                ConfKey::ActiveSet => active = Some(e.value.trim().to_owned()),
                ConfKey::ExecutionRate => {}
            }
        }
        // `default` first: a set the file creates starts from it (Decision above).
        let default_values = named.remove(DEFAULT_SET).unwrap_or_default();
        for (set, values) in core::iter::once((DEFAULT_SET, default_values)).chain(named) {
            let mut p = match next.sets.get(set) {
                Some(p) => p.clone(),
                None => next
                    .sets
                    .get(DEFAULT_SET)
                    .cloned()
                    .unwrap_or_else(P::defaults),
            };
            for (i, v) in values {
                p.put(i, v);
            }
            next.sets.insert(set.to_owned(), p);
        }
        let set = active.unwrap_or_else(|| next.active_set.clone());
        next.activate_set(&set)?;
        *self = next;
        Ok(())
    }

    fn to_conf(&self) -> String {
        let mut out =
            String::from("# -*- Property -*-\n# Written by rtnav (OpenRTM .conf syntax).\n");
        out += &format!("configuration.active_config: {}\n", self.active_set);
        for (set, values) in &self.sets {
            out.push('\n');
            for (i, spec) in P::SPECS.iter().enumerate() {
                out += &format!("conf.{set}.{}: {}\n", spec.name, spec.format(values.get(i)));
            }
        }
        if !self.widgets.is_empty() {
            out.push('\n');
            for (i, w) in &self.widgets {
                out += &format!("conf.__widget__.{}: {w}\n", P::SPECS[*i].name);
            }
        }
        out
    }
}
