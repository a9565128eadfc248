//! The whole system's configuration as one OpenRTM `.conf` text (spec §1 "Configuration
//! parameters"; the teaching page's export and import).
//!
//! **Decision (bundle format)**: the text is a sequence of blocks, one per component that
//! has configuration parameters, in [`ComponentKind::ALL`] order. Each block starts with a
//! marker comment line `# [InstanceName]` (e.g. `# [LocalPathPlanning0]`) followed by exactly
//! that component's own `.conf` text as [`ConfigAccess::to_conf`] writes it. A marker is a
//! comment to OpenRTM, so every block — cut out with its marker or without — is a valid
//! `.conf` file for that component alone. The whole text also reads as one properties file
//! (the markers are comments), but keys such as `conf.default.dmin` recur in several blocks:
//! only the markers say whose they are.
//! Before the first marker only comments and blank lines may stand (the export writes one
//! comment line there).
//!
//! ```text
//! # rtnav configuration: one OpenRTM .conf block per component, each after its marker line `# [InstanceName]`.
//!
//! # [PhysicsSim0]
//! # -*- Property -*-
//! # Written by rtnav (OpenRTM .conf syntax).
//! configuration.active_config: default
//!
//! conf.default.Mass: 20.0
//! conf.default.YawInertia: 1.0
//! conf.default.ViscousFriction: 0.02
//! conf.default.MaxTorque: 5.0
//!
//! # [MotorControl0]
//! …
//! ```
//!
//! Reading ([`System::load_conf`]) is all-or-nothing: the text is split at the markers, each
//! block is parsed ([`ConfFile::parse`]) and applied to a clone of its component's
//! configuration; only when every block succeeded are the blocks applied to the components.
//! A component without a block keeps its configuration. Errors name the line of the whole
//! file, the component and the problem: an unknown or repeated marker, text before the first
//! marker, an unknown key, a value that is not a number or out of range.

use crate::errors::{ConfBundleError, ConfigError, SystemError};
use crate::rtc::{ConfFile, ConfKey, ConfigAccess, without_bom};

use super::wiring::Wiring;
use crate::system::vocabulary::events::EventKind;
use crate::system::vocabulary::kind::ComponentKind;

/// The first line of a bundle [`Wiring::to_conf`] writes.
pub const CONF_BUNDLE_HEADER: &str = "# rtnav configuration: one OpenRTM .conf block per \
    component, each after its marker line `# [InstanceName]`.";

/// The instance name in a block marker line `# [NAME]`, if `line` is one.
fn marker(line: &str) -> Option<&str> {
    let inner = line
        .trim()
        .strip_prefix('#')?
        .trim()
        .strip_prefix('[')?
        .strip_suffix(']')?
        .trim();
    Some(inner)
}

/// One component's block of a bundle.
struct Block {
    kind: ComponentKind,
    /// 1-based line of the marker.
    marker_line: usize,
    conf: ConfFile,
}

/// Loads `conf` into a clone of `config`: whether the block applies, nothing changed.
/// `conf` applied to a copy of `config`: the `dmin` it would leave, if the component has one.
fn trial(config: &dyn ConfigAccess, conf: &ConfFile) -> Result<Option<f64>, ConfigError> {
    let mut copy = config.boxed_copy();
    copy.load_conf(conf)?;
    Ok(copy.value(DMIN).ok())
}

/// The parameter both planners hold, one value for the system (spec §3 Decision 0.2).
const DMIN: &str = "dmin";

/// The 1-based line a `.conf` problem names, if it names one.
fn problem_line(e: &ConfigError) -> Option<usize> {
    match e {
        ConfigError::UnknownParameter { line, .. }
        | ConfigError::OutOfRange { line, .. }
        | ConfigError::BadValue { line, .. } => *line,
        ConfigError::Syntax { line, .. } => Some(*line),
        _ => None,
    }
}

impl Block {
    /// `problem` as the bundle's error: the line it names, else (an unknown configuration
    /// set) the block's last `configuration.active_config` line, else the marker's.
    fn error(&self, problem: ConfigError) -> crate::Error {
        let line = problem_line(&problem)
            .or_else(|| {
                self.conf
                    .entries
                    .iter()
                    .rev()
                    .find(|e| e.key == ConfKey::ActiveSet)
                    .map(|e| e.line)
            })
            .unwrap_or(self.marker_line);
        ConfBundleError::ConfBlock {
            component: self.kind.instance_name().to_owned(),
            line,
            problem,
        }
        .into()
    }
}

/// A parameter `name` that `kind` does not have, named with its component
/// (`DriveControl.MaxSpeed`), as `rtnav compare` names parameters.
pub(in crate::system) fn unknown_parameter(kind: ComponentKind, name: &str) -> ConfigError {
    ConfigError::UnknownParameter {
        name: format!("{}.{name}", kind.name()),
        line: None,
    }
}

impl Wiring {
    /// A component's configuration parameters, to read (spec §1 "Configuration
    /// parameters"). MapBuilder and MapMaintenance have none.
    pub fn config(&self, kind: ComponentKind) -> crate::Result<&dyn ConfigAccess> {
        let c = self.execution_context().component_dyn(kind.index())?;
        c.configuration_ref().ok_or_else(|| {
            SystemError::NoConfiguration {
                component: kind.name().to_owned(),
            }
            .into()
        })
    }

    fn config_mut(&mut self, kind: ComponentKind) -> crate::Result<&mut dyn ConfigAccess> {
        let c = self.ec_mut().component_dyn_mut(kind.index())?;
        c.configuration().ok_or_else(|| {
            SystemError::NoConfiguration {
                component: kind.name().to_owned(),
            }
            .into()
        })
    }

    /// The components that have configuration parameters, in attachment order.
    pub fn configured_components(&self) -> Vec<ComponentKind> {
        ComponentKind::ALL
            .into_iter()
            .filter(|&k| self.config(k).is_ok())
            .collect()
    }

    /// Sets one parameter (spec §1: `always` at once, `on_activation` pending until the next
    /// activation; out of range refused, the old value stays). `dmin` is one value for the
    /// system (spec §3 Decision 0.2): setting LocalPathPlanning's or GlobalPathPlanning's
    /// sets both, checked on both first.
    pub fn set_param(&mut self, kind: ComponentKind, name: &str, value: f64) -> crate::Result<()> {
        let kinds: &[ComponentKind] = if name == DMIN && kind.holds_dmin() {
            &ComponentKind::DMIN_HOLDERS
        } else {
            core::slice::from_ref(&kind)
        };
        for &k in kinds {
            let config = self.config(k)?;
            let spec = config
                .specs()
                .iter()
                .find(|s| s.name == name)
                .ok_or_else(|| unknown_parameter(k, name))?;
            spec.check(value, None)?;
        }
        for &k in kinds {
            self.config_mut(k)?.set(name, value)?;
        }
        self.fact(EventKind::ParameterSet {
            component: kind.name().to_owned(),
            name: name.to_owned(),
            value,
        });
        self.check_clearance();
        Ok(())
    }

    /// The whole configuration as one OpenRTM `.conf` text: a block per component with
    /// parameters, in attachment order (module documentation).
    pub fn to_conf(&self) -> String {
        let mut out = String::from(CONF_BUNDLE_HEADER);
        out.push('\n');
        for kind in ComponentKind::ALL {
            if let Ok(config) = self.config(kind) {
                out.push('\n');
                out += &format!("# [{}]\n", kind.instance_name());
                out += &config.to_conf();
            }
        }
        out
    }

    /// Reads a bundle (module documentation): every block is checked on a copy first, then
    /// all are applied, or none. `dmin` stays one value (spec §3 Decision 0.2): a block that
    /// sets one planner's `dmin` sets the other's too, and blocks that give the two planners
    /// different values are refused, naming both.
    pub fn load_conf(&mut self, text: &str) -> crate::Result<()> {
        let blocks = self.split_conf(text)?;
        let mut dmins: Vec<(ComponentKind, f64)> = Vec::new();
        for block in &blocks {
            // `split_conf` keeps only components with parameters.
            let checked = trial(self.config(block.kind)?, &block.conf);
            if let Some(dmin) = checked.map_err(|e| block.error(e))? {
                dmins.push((block.kind, dmin));
            }
        }
        if let [(a, da), (b, db)] = dmins[..]
            && da.to_bits() != db.to_bits()
        {
            return Err(SystemError::DminMismatch {
                first: a.instance_name(),
                first_value: da,
                second: b.instance_name(),
                second_value: db,
            }
            .into());
        }
        // Commit: the same blocks on the same configurations, so each succeeds as its trial did.
        for block in &blocks {
            let config = self.config_mut(block.kind)?;
            config.load_conf(&block.conf).map_err(|e| block.error(e))?;
        }
        if let Some(&(_, dmin)) = dmins.first() {
            for kind in ComponentKind::DMIN_HOLDERS {
                self.config_mut(kind)?.set(DMIN, dmin)?;
            }
        }
        self.fact(EventKind::ConfigurationLoaded {
            components: blocks.len(),
        });
        self.check_clearance();
        Ok(())
    }

    fn split_conf(&self, text: &str) -> crate::Result<Vec<Block>> {
        let lines: Vec<&str> = without_bom(text).lines().collect();
        // (kind, 0-based marker index) of each block, in file order.
        let mut starts: Vec<(ComponentKind, usize)> = Vec::new();
        for (i, &raw) in lines.iter().enumerate() {
            let line = i + 1;
            if let Some(name) = marker(raw) {
                let kind = ComponentKind::ALL
                    .into_iter()
                    .find(|k| k.instance_name() == name || k.name() == name)
                    .filter(|&k| self.config(k).is_ok())
                    .ok_or_else(|| ConfBundleError::ConfUnknownComponent {
                        line,
                        name: crate::present::excerpt(name),
                        expected: self
                            .configured_components()
                            .iter()
                            .map(|k| k.instance_name())
                            .collect::<Vec<_>>()
                            .join(", "),
                    })?;
                if let Some(&(_, first)) = starts.iter().find(|(k, _)| *k == kind) {
                    return Err(ConfBundleError::ConfDuplicateComponent {
                        line,
                        component: kind.instance_name().to_owned(),
                        first: first + 1,
                    }
                    .into());
                }
                starts.push((kind, i));
            } else if starts.is_empty() {
                let t = raw.trim();
                if !(t.is_empty() || t.starts_with('#') || t.starts_with('!')) {
                    return Err(ConfBundleError::ConfOutsideBlock {
                        line,
                        text: crate::present::excerpt(raw),
                    }
                    .into());
                }
            }
        }
        let mut blocks = Vec::with_capacity(starts.len());
        for (n, &(kind, start)) in starts.iter().enumerate() {
            let end = starts.get(n + 1).map_or(lines.len(), |&(_, s)| s);
            // The block's own lines, after as many empty lines as precede them, so the
            // parser's line numbers are those of the whole text.
            let mut block_text = "\n".repeat(start + 1);
            for l in &lines[start + 1..end] {
                block_text.push_str(l);
                block_text.push('\n');
            }
            let mut block = Block {
                kind,
                marker_line: start + 1,
                conf: ConfFile::default(),
            };
            block.conf = ConfFile::parse(&block_text).map_err(|e| block.error(e))?;
            blocks.push(block);
        }
        Ok(blocks)
    }
}
