//! A student's script read for `rtnav run --script` and `rtnav check --script` (spec §8):
//! compiled, and the component it stands in for decided — the one `--component` names when
//! given, else the one the script's declaration (`const COMPONENT = "MotorControl";`) names.
//! Whether the script may go there is the core's to say when it loads it (a script declaring
//! another component, a component no script can stand in for).

use std::collections::BTreeMap;

use rtnav::script::{ConsoleKind, DECLARATION, Program, ScriptError};
use rtnav::system::{ComponentKind, ScriptText, System};

/// A script ready to be loaded: where it goes and what it is.
#[derive(Debug, Clone, PartialEq)]
pub struct ScriptHandIn {
    /// The component whose place it takes.
    pub component: ComponentKind,
    /// Its name (a file name) and text, as a set-up carries it.
    pub text: ScriptText,
    /// The component its declaration names, if it has one, and the declaration's line and
    /// column (1-based) when it is found in the text.
    pub declared: Option<(String, Option<(usize, usize)>)>,
}

impl ScriptHandIn {
    /// The scripts of a set-up ([`rtnav::system::Setup::scripts`]): this one in its place.
    pub fn scripts(&self) -> BTreeMap<String, ScriptText> {
        BTreeMap::from([(self.component.name().to_owned(), self.text.clone())])
    }

    /// The core's refusal to load it (`error`), in words, with the declaration's place when
    /// the refusal is about the declaration (a script declaring another component).
    pub fn refusal(&self, error: &rtnav::Error) -> String {
        let words = crate::words::Words::english().error(error);
        match self.declaration_place() {
            Some(place) => format!("{words} (the declaration: {place})"),
            None => words,
        }
    }

    /// The declaration's place as words to put after a refusal that is about it (`line 7,
    /// column 1`), when the script declares a component other than the one it was loaded
    /// into and the declaration was found in the text.
    pub fn declaration_place(&self) -> Option<String> {
        let (declared, at) = self.declared.as_ref()?;
        let (line, column) = (*at)?;
        (declared != self.component.name()).then(|| format!("line {line}, column {column}"))
    }
}

/// Why a script is not loaded (before the core is asked to load it).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ScriptRefusal {
    /// It does not compile, or its top level fails (the error names line and column).
    #[error("{0}")]
    Script(ScriptError),
    /// Neither its declaration nor `--component` names a component.
    #[error(
        "the script declares no component (a top-level `const {DECLARATION} = \"MotorControl\";` \
         or \"DriveControl\") and --component names none"
    )]
    NoComponent,
    /// Its declaration names no component of the system.
    #[error(
        "line {line}, column {column}: the script declares `{DECLARATION} = \"{declared}\"`: {error}"
    )]
    UnknownDeclared {
        /// What it declares.
        declared: String,
        /// The declaration's 1-based line (0 when not found in the text).
        line: usize,
        /// The declaration's 1-based column (0 when not found in the text).
        column: usize,
        /// The core's words for the unknown name.
        error: String,
    },
}

/// `source` (named `name`) compiled, and the component it goes into: `component` when
/// given, else the one it declares.
pub fn script_hand_in(
    name: &str,
    source: &str,
    component: Option<ComponentKind>,
) -> Result<ScriptHandIn, ScriptRefusal> {
    let program = Program::compile(name, source).map_err(ScriptRefusal::Script)?;
    let declared = program
        .declared()
        .map(|d| (d.to_owned(), declaration_at(source)));
    let component = match (component, &declared) {
        (Some(c), _) => c,
        (None, Some((d, at))) => ComponentKind::from_name(d).map_err(|e| {
            let (line, column) = at.unwrap_or((0, 0));
            ScriptRefusal::UnknownDeclared {
                declared: rtnav::present::excerpt(d),
                line,
                column,
                error: crate::words::Words::english().error(&e.into()),
            }
        })?,
        (None, None) => return Err(ScriptRefusal::NoComponent),
    };
    Ok(ScriptHandIn {
        component,
        text: ScriptText {
            name: name.to_owned(),
            source: source.to_owned(),
        },
        declared,
    })
}

/// The 1-based line and column of the script's declaration (`const COMPONENT = …`): the
/// first line that starts, after blanks, with `const` and then `COMPONENT`.
pub fn declaration_at(source: &str) -> Option<(usize, usize)> {
    source.lines().enumerate().find_map(|(i, line)| {
        let rest = line.trim_start();
        let after = rest.strip_prefix("const")?;
        let name = after.trim_start();
        let is_declaration = after.starts_with(char::is_whitespace)
            && name.starts_with(DECLARATION)
            && !name[DECLARATION.len()..].starts_with(|c: char| c.is_alphanumeric() || c == '_');
        is_declaration.then(|| (i + 1, line.chars().count() - rest.chars().count() + 1))
    })
}

/// A component name as `--component` takes it (`MotorControl`, or its instance name
/// `MotorControl0`).
pub fn parse_component(text: &str) -> Result<ComponentKind, String> {
    ComponentKind::from_name(text).map_err(|e| crate::words::Words::english().error(&e.into()))
}

/// How the script in `kind`'s place failed in `system`'s run, if it did: its last error
/// (the action, line, column and what went wrong) and when it first came \[s of simulated
/// time\], e.g. `on_execute, line 12, column 9: … (at 0.1 s)`.
pub fn script_failure(system: &System, kind: ComponentKind) -> Option<String> {
    let script = system.wiring().script(kind)?;
    let error = script.last_error()?;
    let words = crate::words::Words::english().error(&rtnav::Error::Script(error.clone()));
    let first = script
        .console()
        .lines()
        .filter(|l| {
            l.kind == ConsoleKind::Error
                && l.text == error.message()
                && Some(l.action.as_str()) == error.action()
        })
        .map(|l| l.first_s)
        .last();
    Some(match first {
        Some(t) => format!("{words} (at {} s)", rtnav::present::number(round3(t))),
        None => words,
    })
}

/// `v` to three decimals.
fn round3(v: f64) -> f64 {
    libm::round(v * 1000.0) / 1000.0
}

#[cfg(test)]
mod tests {
    use super::declaration_at;

    #[test]
    fn the_declaration_is_found_at_its_line_and_column() {
        let text = "// const COMPONENT = \"x\";\n\n  const COMPONENT = \"MotorControl\";\n";
        assert_eq!(declaration_at(text), Some((3, 3)));
        assert_eq!(declaration_at("const COMPONENTS = 1;\n"), None);
        assert_eq!(declaration_at("constant COMPONENT\n"), None);
    }
}
