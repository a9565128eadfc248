//! The command line's words for the core's facts: the page's English catalogue
//! (`web/i18n/en.json`, the one source of English), said by the rules of the page's
//! `web/js/say.js` and `web/js/i18n.js`, so the command line and the page say the same fact in
//! the same words. The core hands every fact over as data — a kind and its fields — and this
//! module says it:
//!
//! - an event (`EventKind`, as `EventView`'s `{kind, data}`) → `event.<Kind>` (and its forms);
//! - a reason (`rtnav::Reason`, `{kind, …}`) → `reason.<kind>`, a nested error through
//!   `error.<Area>.<Kind>`;
//! - an error (`rtnav::Error`, its `ErrorDetail`) → `error.<Area>.<Kind>`;
//! - a request (`InputSummary`) → `input.<Kind>`;
//! - the robot's status (`Status`) → `status.<kind>`;
//! - a component's activity (`ComponentActivity`) → `rtcstatus.<kind>`;
//! - a parameter's warning (`ParameterWarning`) → `warning.<kind>`.
//!
//! Placeholders are those of `i18n.js`'s `fill`: `{name}`, a dotted path `{pose.x}` /
//! `{cell.0}`, and a format after a colon: `.N` (N decimals), `n` (`rtnav::present::number`),
//! `deg.N` (radians in degrees, N decimals); a list is joined with ", "; a placeholder without
//! a value stays as written. A key's `.one` form is its singular.

use std::sync::OnceLock;

use rtnav::Reason;
use rtnav::system::{
    ComponentActivity, EndReason, EventKind, EventView, InputSummary, ParameterWarning, Status,
};
use serde::Serialize;
use serde_json::{Map, Value, json};

/// The English catalogue, as the page loads it.
const ENGLISH: &str = include_str!("../../web/i18n/en.json");

/// A catalogue: key → template.
#[derive(Debug, Clone)]
pub struct Words {
    text: Map<String, Value>,
}

/// The object of `value`'s fields (empty for anything but an object).
fn fields_of(value: Value) -> Map<String, Value> {
    match value {
        Value::Object(m) => m,
        _ => Map::new(),
    }
}

/// `value` as data (`Null` if it does not serialize).
fn data<T: Serialize>(value: &T) -> Value {
    serde_json::to_value(value).unwrap_or(Value::Null)
}

/// Why a text is not a catalogue.
#[derive(Debug, thiserror::Error)]
pub enum CatalogueError {
    /// Not JSON.
    #[error(transparent)]
    Json(#[from] serde_json::Error),
    /// JSON, but not an object.
    #[error("a catalogue is a JSON object of strings")]
    NotAnObject,
}

impl Words {
    /// The English catalogue (`web/i18n/en.json`).
    pub fn english() -> &'static Words {
        static ENGLISH_WORDS: OnceLock<Words> = OnceLock::new();
        ENGLISH_WORDS
            .get_or_init(|| Words::from_json(ENGLISH).unwrap_or(Words { text: Map::new() }))
    }

    /// A catalogue from its JSON text (a flat object of strings).
    pub fn from_json(text: &str) -> Result<Words, CatalogueError> {
        match serde_json::from_str(text)? {
            Value::Object(text) => Ok(Words { text }),
            _ => Err(CatalogueError::NotAnObject),
        }
    }

    /// Whether the catalogue has `key`.
    pub fn has(&self, key: &str) -> bool {
        self.text.contains_key(key)
    }

    /// Every key of the catalogue.
    pub fn keys(&self) -> impl Iterator<Item = &str> {
        self.text.keys().map(String::as_str)
    }

    /// The text of `key` with its placeholders filled from `vars` (the key itself when the
    /// catalogue has none: what the page shows too).
    pub fn t(&self, key: &str, vars: &Value) -> String {
        match self.text.get(key).and_then(Value::as_str) {
            Some(text) => fill(text, vars),
            None => key.to_owned(),
        }
    }

    /// `key`, or its `.one` form when the count is one (English's singular).
    fn counted(&self, key: &str, n: &Value) -> String {
        let one = format!("{key}.one");
        if n.as_f64() == Some(1.0) && self.has(&one) {
            one
        } else {
            key.to_owned()
        }
    }

    /// Words that arrive as given, in the catalogue's words when it has them.
    fn given(&self, v: &Value) -> Value {
        match v.as_str() {
            Some(s) if self.has(&format!("word.{s}")) => {
                Value::String(self.t(&format!("word.{s}"), &Value::Null))
            }
            _ => v.clone(),
        }
    }

    // ------------------------------------------------------------------------ errors

    /// An error of the core in words: its `ErrorDetail` through `error.<Area>.<Kind>`, or its
    /// own `Display` where the catalogue has no words for it.
    pub fn error(&self, e: &rtnav::Error) -> String {
        self.detail_text(&data(&e.detail()))
            .unwrap_or_else(|| e.to_string())
    }

    /// The fields of an error detail as `error.<Area>.<Kind>`'s placeholders want them.
    fn error_vars(&self, d: &Value) -> Value {
        const OPTIONAL: [&str; 2] = ["line", "index"];
        let empty = Map::new();
        let fields = d.get("fields").and_then(Value::as_object).unwrap_or(&empty);
        let mut vars = Map::new();
        for (k, v) in fields {
            let said = if v.is_null() && !OPTIONAL.contains(&k.as_str()) {
                Value::String("NaN".to_owned())
            } else if v.get("area").is_some() && v.get("kind").is_some() && v.is_object() {
                Value::String(self.detail_text(v).unwrap_or_default())
            } else {
                self.given(v)
            };
            vars.insert(k.clone(), said);
        }
        let say = |key: String| Value::String(self.t(&key, &Value::Null));
        if let Some(r) = fields.get("request").and_then(Value::as_str) {
            vars.insert("request".into(), say(format!("request.{r}")));
        }
        if let Some(ty) = fields.get("type").and_then(Value::as_str)
            && self.has(&format!("params.type.{ty}"))
        {
            vars.insert("type".into(), say(format!("params.type.{ty}")));
        }
        for (name, at) in [("line", "at_line"), ("index", "at_index")] {
            if let Some(v) = fields.get(name) {
                let text = if v.is_null() {
                    String::new()
                } else {
                    self.t(&format!("error.{at}"), &json!({ name: v }))
                };
                vars.insert(at.into(), Value::String(text));
            }
        }
        if let Some(i) = fields.get("index").and_then(Value::as_f64) {
            vars.insert("previous".into(), json!(i - 1.0));
        }
        if let Some(v) = fields.get("non_negative") {
            let text = if v.as_bool() == Some(true) {
                self.t("error.System.non_negative", &Value::Null)
            } else {
                String::new()
            };
            vars.insert("non_negative".into(), Value::String(text));
        }
        Value::Object(vars)
    }

    /// An error detail (`{area, kind, fields, file?, scenario?}`) in words, or `None` when
    /// the catalogue has no words for it.
    fn detail_text(&self, d: &Value) -> Option<String> {
        let area = d.get("area")?.as_str()?;
        let kind = d.get("kind")?.as_str()?;
        let key = format!("error.{area}.{kind}");
        if !self.has(&key) {
            return None;
        }
        let mut text = self.t(&key, &self.error_vars(d));
        if let Some(file) = d.get("file").filter(|f| !f.is_null()) {
            text = self.t("error.in_file", &json!({ "file": file, "error": text }));
        }
        if let Some(scenario) = d.get("scenario").filter(|s| !s.is_null()) {
            text = self.t(
                "error.in_scenario",
                &json!({ "scenario": scenario, "error": text }),
            );
        }
        Some(text)
    }

    // ----------------------------------------------------------------------- reasons

    /// A reason (`rtnav::Reason`) in words.
    pub fn reason(&self, r: &Reason) -> String {
        self.reason_text(&data(r))
    }

    fn reason_text(&self, r: &Value) -> String {
        let Some(kind) = r.get("kind").and_then(Value::as_str) else {
            return String::new();
        };
        let error = |key: &str| {
            r.get(key)
                .and_then(|e| self.detail_text(e))
                .unwrap_or_default()
        };
        let vars = match kind {
            "error" | "course_refused" => json!({ "error": error("error") }),
            "map_update_refused" => {
                json!({ "component": r.get("component"), "error": error("error") })
            }
            "bump" => {
                let mut report = fields_of(r.get("report").cloned().unwrap_or(Value::Null));
                report.insert("t".into(), json!(seconds_of(r.get("report"))));
                Value::Object(report)
            }
            "injected_fault" => {
                json!({ "words": self.given(r.get("words").unwrap_or(&Value::Null)) })
            }
            _ => r.clone(),
        };
        self.t(&format!("reason.{kind}"), &vars)
    }

    /// A parameter's warning in words.
    pub fn warning(&self, w: &ParameterWarning) -> String {
        let mut vars = fields_of(data(w));
        let kind = vars
            .get("kind")
            .and_then(Value::as_str)
            .unwrap_or_default()
            .to_owned();
        let half = vars
            .get("grid_size")
            .and_then(Value::as_f64)
            .map_or(Value::Null, |g| json!(g / 2.0));
        vars.insert("half".into(), half);
        self.t(&format!("warning.{kind}"), &Value::Object(vars))
    }

    // ---------------------------------------------------------------------- requests

    /// A request (`InputSummary`) in words.
    pub fn input(&self, request: &InputSummary) -> String {
        self.input_text(&data(request))
    }

    fn input_text(&self, request: &Value) -> String {
        let kind = request.get("kind").and_then(Value::as_str).unwrap_or("");
        self.t(&format!("input.{kind}"), request)
    }

    // ------------------------------------------------------------------------ events

    /// An event in words (without its time).
    pub fn event(&self, kind: &EventKind) -> String {
        let view = EventView::of(&rtnav::system::SystemEvent {
            time_ns: 0,
            kind: kind.clone(),
        });
        self.event_text(&view.kind, &view.data)
    }

    /// An event of the log, `[   12.345 s] …`: its time and its words.
    pub fn logged(&self, e: &rtnav::system::SystemEvent) -> String {
        format!(
            "[{:9.3} s] {}",
            e.time_ns as f64 * 1e-9,
            self.event(&e.kind)
        )
    }

    /// An event (`{kind, data}`, as `EventView` carries it) in words.
    pub fn event_text(&self, kind: &str, d: &Value) -> String {
        let field = |k: &str| d.get(k).cloned().unwrap_or(Value::Null);
        let escape = || {
            let steps = field("escaped");
            if steps.as_f64().is_some_and(|s| s > 0.0) {
                Value::String(self.t("event.escape", &json!({ "steps": steps })))
            } else {
                Value::String(String::new())
            }
        };
        let word = |key: &str| Value::String(self.t(key, &Value::Null));
        let (key, extra): (String, Value) = match kind {
            "GoalSet" => {
                let key = if field("placed").as_bool() == Some(true) {
                    "event.GoalSet"
                } else {
                    "event.GoalSet.new"
                };
                let dir = if field("direction").as_str() == Some("Backward") {
                    "dir.backward"
                } else {
                    "dir.forward"
                };
                (key.into(), json!({ "dir": word(dir) }))
            }
            "GlobalPlan" => {
                let why = field("reason")
                    .as_str()
                    .map(|r| format!("event.GlobalPlan.{r}"))
                    .filter(|k| self.has(k))
                    .map_or(Value::String(String::new()), |k| word(&k));
                (
                    "event.GlobalPlan".into(),
                    json!({ "why": why, "escape": escape() }),
                )
            }
            "LocalPlanSent" => {
                let key = if field("cells").as_f64() == Some(0.0) {
                    "event.LocalPlanSent.empty"
                } else if field("replanned").as_bool() == Some(true) {
                    "event.LocalPlanSent"
                } else {
                    "event.LocalPlanSent.global"
                };
                (key.into(), json!({ "escape": escape() }))
            }
            "PlanningFailed" | "ComponentError" => (
                format!("event.{kind}"),
                json!({ "reason": self.reason_text(&field("reason")) }),
            ),
            "Bump" => (
                "event.Bump".into(),
                json!({ "t_s": seconds_of(d.get("report")) }),
            ),
            "SafetyStop" => {
                let key = if field("replanning").as_bool() == Some(true) {
                    "event.SafetyStop.replanning"
                } else {
                    "event.SafetyStop"
                };
                (key.into(), json!({}))
            }
            "FaultInjected" => (
                "event.FaultInjected".into(),
                json!({ "reason": self.given(&field("reason")) }),
            ),
            "ClearanceWarning" => (
                "event.ClearanceWarning".into(),
                json!({ "half": field("grid_size").as_f64().map(|g| g / 2.0) }),
            ),
            "RequestRefused" => {
                let source = field("source");
                (
                    "event.RequestRefused".into(),
                    json!({
                        "source": word(&format!("source.{}", source.as_str().unwrap_or(""))),
                        "request": self.input_text(&field("request")),
                        "reason": self.reason_text(&field("reason")),
                    }),
                )
            }
            _ => (format!("event.{kind}"), json!({})),
        };
        let mut vars = fields_of(d.clone());
        vars.extend(fields_of(extra));
        self.t(&key, &Value::Object(vars))
    }

    // ------------------------------------------------------------------------ status

    /// What the robot is doing (`Status`) in words.
    pub fn status(&self, status: &Status) -> String {
        let mut fields = fields_of(data(status));
        let kind = match fields.remove("kind") {
            Some(Value::String(k)) => k,
            _ => String::new(),
        };
        self.status_text(&kind, &Value::Object(fields))
    }

    /// A status (its kind and fields, as the telemetry's `status_kind` and `status_fields`)
    /// in words.
    pub fn status_text(&self, kind: &str, fields: &Value) -> String {
        let mut vars = fields_of(fields.clone());
        for name in ["reason", "retrying"] {
            if let Some(r) = fields.get(name).filter(|r| r.is_object()) {
                vars.insert(name.into(), Value::String(self.reason_text(r)));
            }
        }
        if let Some(d) = fields.get("direction").and_then(Value::as_str) {
            let said = self.t(&format!("status.direction.{d}"), &Value::Null);
            vars.insert("direction".into(), Value::String(said));
        }
        if let Some(m) = fields.get("motion").and_then(Value::as_str) {
            let said = self.t(&format!("status.motion.{m}"), &Value::Null);
            vars.insert("motion".into(), Value::String(said));
        }
        let key = match kind {
            "waiting_for_plan" if fields.get("retrying").is_some_and(|r| !r.is_null()) => {
                "status.waiting_for_plan.retrying".to_owned()
            }
            "component_error" if fields.get("reason").is_none_or(Value::is_null) => {
                "status.component_error.no_reason".to_owned()
            }
            _ => format!("status.{kind}"),
        };
        let said = self.t(&key, &Value::Object(vars));
        // The session's clock stands still: the cause is said with the status.
        if fields.get("paused") == Some(&Value::Bool(true)) {
            return self.t("status.paused", &json!({ "status": said }));
        }
        said
    }

    // ------------------------------------------------------------------- run outcomes

    /// Why a run ended (`EndReason`) in words: the event or status that ended it, else
    /// `outcome.<kind>`.
    pub fn end_reason(&self, reason: &EndReason) -> String {
        match reason {
            EndReason::Event { event } => self.event(event),
            EndReason::Status { status } => self.status(status),
            EndReason::ComponentError {
                component,
                reason: Some(r),
            } => self.t(
                "outcome.component_error",
                &json!({ "component": component, "reason": self.reason(r) }),
            ),
            EndReason::ComponentError {
                component,
                reason: None,
            } => self.t(
                "outcome.component_error.no_reason",
                &json!({ "component": component }),
            ),
            EndReason::Halted => self.t("outcome.halted", &Value::Null),
            EndReason::TimeLimit { seconds } => {
                self.t("outcome.time_limit", &json!({ "seconds": seconds }))
            }
            EndReason::Running => self.t("outcome.running", &Value::Null),
        }
    }

    // -------------------------------------------------------------------- components

    /// What a component is doing or holds (`ComponentActivity`) in words.
    pub fn activity(&self, activity: &ComponentActivity) -> String {
        let a = data(activity);
        let kind = a.get("kind").and_then(Value::as_str).unwrap_or("");
        let field = |k: &str| a.get(k).cloned().unwrap_or(Value::Null);
        let word = |key: &str| Value::String(self.t(key, &Value::Null));
        let (key, extra): (String, Value) = match kind {
            "in_error" if a.get("reason").is_some_and(|r| !r.is_null()) => (
                "rtcstatus.in_error.because".into(),
                json!({ "reason": self.reason_text(&field("reason")) }),
            ),
            "in_error" => ("rtcstatus.in_error".into(), json!({})),
            "updates_sent" => (
                self.counted("rtcstatus.updates_sent", &field("updates")),
                json!({}),
            ),
            "bumps" => {
                let touching = if field("touching").as_bool() == Some(true) {
                    word("rtcstatus.touching")
                } else {
                    Value::String(String::new())
                };
                (
                    self.counted("rtcstatus.bumps", &field("bumps")),
                    json!({ "touching": touching }),
                )
            }
            "waiting_for" => {
                let and = self.t("rtcstatus.waiting_for.and", &Value::Null);
                let inputs: Vec<String> = field("inputs")
                    .as_array()
                    .map(|a| a.iter().map(|v| show(v, "")).collect())
                    .unwrap_or_default();
                (
                    "rtcstatus.waiting_for".into(),
                    json!({ "inputs": inputs.join(&and) }),
                )
            }
            "safe_stop" => (
                "rtcstatus.safe_stop".into(),
                json!({
                    "output": word(&format!("rtcstatus.zero.{}", show(&field("output"), ""))),
                    "reason": self.reason_text(&field("reason")),
                }),
            ),
            "route_failed" => (
                "rtcstatus.route_failed".into(),
                json!({ "reason": self.reason_text(&field("reason")) }),
            ),
            "local_planning" => {
                let holds: Vec<String> = field("holds")
                    .as_array()
                    .map(|a| {
                        a.iter()
                            .map(|h| self.t(&format!("held.{}", show(h, "")), &Value::Null))
                            .collect()
                    })
                    .unwrap_or_default();
                let holds = if holds.is_empty() {
                    self.t("held.nothing", &Value::Null)
                } else {
                    holds.join(&self.t("held.separator", &Value::Null))
                };
                let retrying = if field("retrying").as_bool() == Some(true) {
                    word("rtcstatus.retrying")
                } else {
                    Value::String(String::new())
                };
                (
                    self.counted("rtcstatus.local_planning", &field("made")),
                    json!({ "holds": holds, "retrying": retrying }),
                )
            }
            _ => (format!("rtcstatus.{kind}"), json!({})),
        };
        let mut vars = fields_of(a.clone());
        vars.extend(fields_of(extra));
        self.t(&key, &Value::Object(vars))
    }
}

/// The seconds of a bump report's `tm` (`{sec, nsec}`), as the page reckons them.
fn seconds_of(report: Option<&Value>) -> f64 {
    let tm = report.and_then(|r| r.get("tm"));
    let part = |k: &str| {
        tm.and_then(|t| t.get(k))
            .and_then(Value::as_f64)
            .unwrap_or(0.0)
    };
    part("sec") + part("nsec") * 1e-9
}

/// `vars`' value at a dotted path (`pose.x`, `cell.0`), if there is one.
fn at<'a>(vars: &'a Value, path: &str) -> Option<&'a Value> {
    path.split('.').try_fold(vars, |v, part| match v {
        Value::Object(m) => m.get(part),
        Value::Array(a) => part.parse::<usize>().ok().and_then(|i| a.get(i)),
        _ => None,
    })
}

/// A number as JavaScript's `String(v)` writes it (what the page shows for a placeholder
/// without a format).
fn js_number(v: f64) -> String {
    if v.is_nan() {
        return "NaN".to_owned();
    }
    if v.is_infinite() {
        return if v > 0.0 { "Infinity" } else { "-Infinity" }.to_owned();
    }
    if v == 0.0 {
        return "0".to_owned();
    }
    let a = v.abs();
    if (1e-6..1e21).contains(&a) {
        return format!("{v}");
    }
    // Exponent form: Rust's `1e21` / `1e-7` is JavaScript's `1e+21` / `1e-7`.
    let s = format!("{v:e}");
    match s.split_once('e') {
        Some((m, e)) if !e.starts_with('-') => format!("{m}e+{e}"),
        _ => s,
    }
}

/// A placeholder's value as text (`i18n.js`'s `show`): `fmt` empty (a whole number as it
/// is, any other number as `present::number`; a list joined with ", "), `link` (a
/// connection's id with an arrow for its `->`), `.N` (N decimals, no minus on a zero), `n` (`present::number`) or `deg.N`
/// (radians in degrees).
fn show(v: &Value, fmt: &str) -> String {
    match v {
        Value::Array(items) => items
            .iter()
            .map(|x| show(x, fmt))
            .collect::<Vec<_>>()
            .join(", "),
        Value::Null if fmt.is_empty() => String::new(),
        Value::Null => "NaN".to_owned(),
        // A data connection's id (`A.out->B.in`) as people read it: an arrow, not "->".
        Value::String(s) if fmt == "link" => s.replacen("->", " → ", 1),
        Value::String(s) => s.clone(),
        Value::Bool(b) => b.to_string(),
        Value::Object(_) => "[object Object]".to_owned(),
        Value::Number(n) => {
            let x = n.as_f64().unwrap_or(f64::NAN);
            if fmt.is_empty() {
                // A whole number as it is; any other to six significant digits, never the
                // 17 of a float's shortest form (`0.30000000000000004 m`).
                return match (n.as_i64(), n.as_u64()) {
                    (Some(i), _) => i.to_string(),
                    (_, Some(u)) => u.to_string(),
                    _ if x.fract() == 0.0 => js_number(x),
                    _ => rtnav::present::number(x),
                };
            }
            if fmt == "n" {
                return rtnav::present::number(x);
            }
            let (x, digits) = match fmt.strip_prefix("deg") {
                Some(rest) => ((x * 180.0) / core::f64::consts::PI, rest),
                None => (x, fmt),
            };
            let digits = digits
                .strip_prefix('.')
                .unwrap_or(digits)
                .parse::<usize>()
                .unwrap_or(0);
            // Never "-0.00" (a heading of −1e-17 rad is 0.0°).
            rtnav::present::fixed(x, digits)
        }
    }
}

/// `text` with its placeholders filled from `vars` (`i18n.js`'s `fill`).
pub fn fill(text: &str, vars: &Value) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(open) = rest.find('{') {
        out.push_str(&rest[..open]);
        let after = &rest[open + 1..];
        let placeholder = after.find('}').and_then(|close| {
            let inner = &after[..close];
            let (path, fmt) = inner.split_once(':').unwrap_or((inner, ""));
            let word = |s: &str| {
                !s.is_empty()
                    && s.chars()
                        .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '.')
            };
            let well_formed = word(path) && (fmt.is_empty() && !inner.contains(':') || word(fmt));
            well_formed.then_some((close, path, fmt))
        });
        match placeholder {
            Some((close, path, fmt)) => {
                match at(vars, path) {
                    Some(v) => out.push_str(&show(v, fmt)),
                    None => out.push_str(&rest[open..open + close + 2]),
                }
                rest = &after[close + 1..];
            }
            None => {
                out.push('{');
                rest = after;
            }
        }
    }
    out.push_str(rest);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn placeholders_are_filled_as_the_page_fills_them() {
        let vars = json!({
            "pose": { "x": 1.23456, "theta": core::f64::consts::FRAC_PI_2 },
            "cell": [15, 16], "v": 0.5, "n": 3, "none": null, "list": ["a", "b"],
        });
        assert_eq!(
            fill(
                "{pose.x:.2} m {pose.theta:deg.1}° {cell.0}, {cell.1}",
                &vars
            ),
            "1.23 m 90.0° 15, 16"
        );
        assert_eq!(
            fill("{v} {n} {v:n} {none} {none:.2}", &vars),
            "0.5 3 0.5  NaN"
        );
        assert_eq!(
            fill("{list} {missing} {a b} {", &vars),
            "a, b {missing} {a b} {"
        );
        assert_eq!(js_number(1e21), "1e+21");
        assert_eq!(js_number(1e-7), "1e-7");
        assert_eq!(js_number(0.1 + 0.2), "0.30000000000000004");
        // A number without a format is shown to six significant digits, a whole one as it is.
        let raw = json!({ "d": 0.1 + 0.2, "x": 196.2887221472689, "a": core::f64::consts::FRAC_PI_4, "w": 2.0 });
        let cut =
            json!({ "connection": "DriveControl.TargetVelocity->MotorControl.TargetVelocity" });
        assert_eq!(
            fill("cut {connection:link}", &cut),
            "cut DriveControl.TargetVelocity → MotorControl.TargetVelocity"
        );
        assert_eq!(
            fill("{d} m ({x}, …) {a} rad {w}", &raw),
            "0.3 m (196.289, …) 0.785398 rad 2"
        );
    }
}
