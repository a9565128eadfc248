//! The fuzz target for components a student writes (spec §8, Decisions 0.4): scripts, the one
//! input of the system that is code. Target `script`.
//!
//! **Inputs**: the scripts of `fixtures/scripts/` (every `.rhai` file, its folders' included:
//! the reference, broken, exercise and class scripts; read at run time, by path), their byte
//! mutations (the runner's), and what [`Scripts::generate`] makes: a fixture mutated token
//! by token (a token dropped, repeated, swapped or replaced, a hostile
//! statement put into an action, a block wrapped in a loop, a bracket repeated thousands of
//! times), or a script made from scratch out of the component's real ports and parameters
//! and hostile statements — endless and long loops, recursion, strings, arrays and maps that
//! grow past their bounds, closures kept in the state, deep nesting, huge literals,
//! `throw`, bad port use — or random tokens.
//!
//! **Each input**:
//!
//! 1. `Program::compile` must return `Ok` or a [`ScriptError`] whose text is short
//!    ([`ERROR_CHARS`]) — never panic. A script that does not compile is also loaded, as
//!    `Input::LoadScript`, into a system kept for it: refused, and the system's
//!    [snapshot](snapshot) unchanged.
//! 2. A script that compiles is loaded into a copy of open_field's set-up (planned, the
//!    planners Active, MotorControl and DriveControl Inactive), in MotorControl's or
//!    DriveControl's place — the one it declares, else one chosen from the input, and now and
//!    then a place it cannot take (Localization, or the other one while it declares one),
//!    which must be refused. A refused load must leave the snapshot unchanged; an accepted
//!    one must leave the script Inactive in its place.
//! 3. Everything is activated and the system runs for 70 to 310 ticks (1 ms each), each
//!    tick timed: one over [`TICK_LIMIT`] is a hang. On tick [`PROBE_TICK`], while the
//!    script's component is Active, loading another script there and putting the built-in
//!    back must both be refused with nothing changed; so must loading a script that does not
//!    compile, whatever the state. A copy of the system (`System::try_clone`, a replay's
//!    checkpoint) is taken there and run after the original over the same [`TWIN_TICKS`]
//!    ticks: the two must end identical, trace hash and the script's state included (a copy
//!    that shares state with its original — a closure's captured variable — would not).
//! 4. Everything is deactivated and reset, and the built-in component put back: accepted
//!    when the script's component is Inactive (spec §8: "the built-in component can always be
//!    put back"), else refused with nothing changed; 20 more ticks with the built-in.
//!
//! A script that spends its whole budget every tick makes an input long (each such action
//! costs milliseconds): the run stops stepping once the input has spent [`RUN_WALL`], well
//! within the runner's limit of one input ([`super::SLOW`]); the checks of steps 3 and 4 are
//! made either way.

use std::fmt::Write as _;
use std::path::Path;
use std::time::{Duration, Instant};

use rtnav::components::{DriveControlParams, MotorControlParams};
use rtnav::rtc::{LifecycleState, ParameterSet};
use rtnav::script::{Program, ScriptError};
use rtnav::system::{
    BuildOptions, ComponentKind, Input, MemoryResolver, Scenario, Setup, System, setup,
};

use super::system::{fingerprint, first_difference};
use super::{Case, INTERESTING_NUMBERS, REFUSED, Target};
use crate::rng::{Rng, name_hash};

/// The longest one tick may take: 2 s (an action is bounded by its operations budget, a few
/// milliseconds). The same in a debug build: the work is the core's and the engine's, which
/// the workspace's `dev` profile optimises.
pub const TICK_LIMIT: Duration = Duration::from_secs(2);

/// The wall time after which an input stops stepping (its checks are made either way).
pub const RUN_WALL: Duration = Duration::from_millis(250);

/// The longest text a script's error may have \[characters\]: a string can hold 64 KiB, and
/// an error may quote one that was thrown; anything longer quotes the input itself.
pub const ERROR_CHARS: usize = rtnav::script::engine::STRING_BYTES + 1024;

/// The tick on which loading over an Active component is tried (MotorControl has run 30
/// times, DriveControl twice).
pub const PROBE_TICK: u64 = 30;

/// The ticks a checkpoint's copy and its original are run and compared.
pub const TWIN_TICKS: u64 = 40;

/// The places a script can take.
const PLACES: [ComponentKind; 2] = [ComponentKind::MotorControl, ComponentKind::DriveControl];

/// The target `script`.
#[derive(Debug)]
pub struct Scripts {
    seeds: Vec<Case>,
    scenario: Scenario,
    files: MemoryResolver,
    /// Built on the first input (building plans open_field's route).
    systems: Option<Systems>,
}

/// The systems of the target.
#[derive(Debug)]
struct Systems {
    /// open_field's set-up: planned, the planners Active, no script anywhere.
    base: System,
    /// A copy that every script that does not compile is loaded into (refused), and its
    /// snapshot.
    idle: System,
    idle_snapshot: String,
}

/// The targets of this module (none without open_field's fixtures under `root`).
pub fn targets(root: &Path) -> Vec<Box<dyn Target>> {
    Scripts::new(root)
        .map(|t| Box::new(t) as Box<dyn Target>)
        .into_iter()
        .collect()
}

impl Scripts {
    /// The target: its seeds the `.rhai` files under `root/fixtures/scripts` (by path), its
    /// system open_field's set-up (`None` if the scenario or its map cannot be read).
    pub fn new(root: &Path) -> Option<Self> {
        let mut files = Vec::new();
        rhai_files(&root.join("fixtures/scripts"), &mut files);
        files.sort();
        let seeds = files
            .iter()
            .filter_map(|p| std::fs::read(p).ok())
            .map(Case::one)
            .collect();
        let text = std::fs::read_to_string(root.join("fixtures/scenarios/open_field.json")).ok()?;
        let scenario = Scenario::from_json(&text).ok()?;
        let mut files = MemoryResolver::new();
        let map = "fixtures/maps/scenarios/open_field.json";
        files.insert(map, std::fs::read(root.join(map)).ok()?);
        Some(Self {
            seeds,
            scenario,
            files,
            systems: None,
        })
    }

    /// The systems, built the first time.
    fn systems(&mut self) -> Result<&mut Systems, String> {
        if self.systems.is_none() {
            let base = setup::build(
                &self.scenario,
                &self.files,
                &Setup::of(&self.scenario),
                BuildOptions::default(),
            )
            .map_err(|e| format!("open_field's set-up: {e}"))?;
            let idle = base.try_clone().ok_or("the set-up could not be copied")?;
            let idle_snapshot = snapshot(&idle);
            self.systems = Some(Systems {
                base,
                idle,
                idle_snapshot,
            });
        }
        self.systems.as_mut().ok_or_else(|| "no systems".to_owned())
    }
}

/// The `.rhai` files under `dir`, its folders' included.
fn rhai_files(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
    for path in std::fs::read_dir(dir)
        .into_iter()
        .flatten()
        .filter_map(|e| e.ok().map(|e| e.path()))
    {
        if path.is_dir() {
            rhai_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rhai") {
            out.push(path);
        }
    }
}

/// What a caller can observe of a system ([`fingerprint`]), and of each script in a
/// component's place: its name, a hash of its text, its state, its console and its last
/// error.
pub fn snapshot(s: &System) -> String {
    let mut out = fingerprint(s);
    for kind in PLACES {
        match s.wiring().script(kind) {
            Some(script) => {
                let program = script.program();
                let console: Vec<String> =
                    script.console().lines().map(|l| format!("{l:?}")).collect();
                let _ = write!(
                    out,
                    "\n{kind:?}: script {:?} ({} bytes, {:016x}), state {:016x}, console {} \
                     lines {:016x} ({} dropped), last error {:?}",
                    program.name(),
                    program.source().len(),
                    name_hash(program.source()),
                    name_hash(&format!("{:?}", script.state())),
                    console.len(),
                    name_hash(&console.join("\n")),
                    script.console().dropped(),
                    script.last_error()
                );
            }
            None => {
                let _ = write!(out, "\n{kind:?}: built-in");
            }
        }
    }
    out
}

/// Applies `input` to `sys`: a refusal must leave it as it was, and with `must_refuse` it
/// must be refused. `Ok(Some(why))` if it was refused, `Ok(None)` if it was accepted; `Err`
/// says what went wrong.
fn refused_without_change(
    sys: &mut System,
    input: &Input,
    what: &str,
    must_refuse: bool,
) -> Result<Option<String>, String> {
    let before = snapshot(sys);
    match sys.apply(input) {
        Ok(()) if must_refuse => Err(format!("{what} was accepted; it must be refused")),
        Ok(()) => Ok(None),
        Err(e) => {
            REFUSED.with(|r| r.set(r.get() + 1));
            let after = snapshot(sys);
            if after != before {
                return Err(format!(
                    "{what} was refused ({e}) but changed the system: {}",
                    first_difference(&after, &before)
                ));
            }
            Ok(Some(e.to_string()))
        }
    }
}

/// A script that does not compile.
const BROKEN: &str = "fn on_execute(rtc) { let x = ; }";

/// A script for `kind`'s place that compiles and does nothing.
fn minimal(kind: ComponentKind) -> String {
    format!("const COMPONENT = \"{}\";\n", kind.name())
}

/// Steps `sys` `ticks` ticks (fewer once `deadline` has passed), timing each; `Err` for a
/// tick over [`TICK_LIMIT`] (`from` numbers the first). Returns the ticks run.
fn run_ticks(
    sys: &mut System,
    ticks: u64,
    deadline: Option<Instant>,
    from: u64,
) -> Result<u64, String> {
    for t in 0..ticks {
        if deadline.is_some_and(|d| Instant::now() > d) {
            return Ok(t);
        }
        let tick = Instant::now();
        sys.step(1);
        let took = tick.elapsed();
        if took > TICK_LIMIT {
            return Err(format!(
                "tick {} took {:.3} s (limit {:.0} s): an action ran past its budget",
                from + t,
                took.as_secs_f64(),
                TICK_LIMIT.as_secs_f64()
            ));
        }
    }
    Ok(ticks)
}

impl Systems {
    /// Step 1 for a script that does not compile: its load is refused, nothing changes.
    fn refuse_broken(&mut self, text: &str) -> Result<(), String> {
        let kind = PLACES[(name_hash(text) & 1) as usize];
        let input = Input::LoadScript {
            component: kind,
            name: "fuzz.rhai".to_owned(),
            source: text.to_owned(),
        };
        match self.idle.apply(&input) {
            Ok(()) => Err(format!(
                "a script that does not compile was loaded into {kind:?}'s place"
            )),
            Err(e) => {
                REFUSED.with(|r| r.set(r.get() + 1));
                let after = snapshot(&self.idle);
                if after != self.idle_snapshot {
                    let diff = first_difference(&after, &self.idle_snapshot);
                    // The next input starts from a clean copy.
                    if let Some(idle) = self.base.try_clone() {
                        self.idle = idle;
                    }
                    return Err(format!("a load refused ({e}) changed the system: {diff}"));
                }
                Ok(())
            }
        }
    }

    /// Steps 2 to 4 for a script that compiles.
    fn load_and_run(&mut self, text: &str, program: &Program) -> Result<(), String> {
        let deadline = Some(Instant::now() + RUN_WALL);
        let h = name_hash(text);
        let declared = program
            .declared()
            .and_then(|d| PLACES.into_iter().find(|k| k.name() == d));
        let chosen = declared.unwrap_or(PLACES[(h & 1) as usize]);
        let (kind, must_refuse) = match (h >> 1) % 16 {
            0 => (ComponentKind::Localization, true),
            1 if declared.is_some() => (
                if chosen == ComponentKind::MotorControl {
                    ComponentKind::DriveControl
                } else {
                    ComponentKind::MotorControl
                },
                true,
            ),
            // A declaration that names no place: refused wherever it goes.
            _ => (chosen, program.declared().is_some() && declared.is_none()),
        };
        let mut sys = self
            .base
            .try_clone()
            .ok_or("the set-up could not be copied")?;
        let load = Input::LoadScript {
            component: kind,
            name: "fuzz.rhai".to_owned(),
            source: text.to_owned(),
        };
        if refused_without_change(&mut sys, &load, "the load", must_refuse)?.is_some() {
            return Ok(());
        }
        if sys.wiring().script(kind).is_none() {
            return Err(format!(
                "the load was accepted, but {kind:?}'s place has no script"
            ));
        }
        let state = sys.component_state(kind);
        if state != LifecycleState::Inactive {
            return Err(format!(
                "the load was accepted, but the script is {state:?}"
            ));
        }
        // An activation may fail (a failing `on_activated`): that is the script's business.
        let _ = sys.apply(&Input::ActivateAll);
        let ticks = PROBE_TICK + TWIN_TICKS + (h >> 8) % 241;
        let ran = run_ticks(&mut sys, PROBE_TICK, deadline, 0)?;
        if sys.component_state(kind) == LifecycleState::Active {
            let other = Input::LoadScript {
                component: kind,
                name: "other.rhai".to_owned(),
                source: minimal(kind),
            };
            refused_without_change(&mut sys, &other, "a load over the Active script", true)?;
            refused_without_change(
                &mut sys,
                &Input::UseBuiltIn { component: kind },
                "putting the built-in back over the Active script",
                true,
            )?;
        }
        let broken = Input::LoadScript {
            component: kind,
            name: "broken.rhai".to_owned(),
            source: BROKEN.to_owned(),
        };
        refused_without_change(&mut sys, &broken, "a script that does not compile", true)?;
        if ran == PROBE_TICK {
            // A checkpoint's copy runs the same ticks after its original.
            let mut twin = sys
                .try_clone()
                .ok_or("the scripted system could not be copied")?;
            let n = run_ticks(&mut sys, TWIN_TICKS, deadline, PROBE_TICK)?;
            let m = run_ticks(&mut twin, n, None, PROBE_TICK)?;
            let (a, b) = (snapshot(&sys), snapshot(&twin));
            if m != n || a != b {
                return Err(format!(
                    "a copy taken on tick {PROBE_TICK} and run the same {n} ticks after its \
                     original differs from it: {}",
                    first_difference(&b, &a)
                ));
            }
        }
        let done = PROBE_TICK + TWIN_TICKS;
        run_ticks(&mut sys, ticks.saturating_sub(done), deadline, done)?;
        let _ = sys.apply(&Input::DeactivateAll);
        let _ = sys.apply(&Input::ResetAll);
        let inactive = sys.component_state(kind) == LifecycleState::Inactive;
        let back = Input::UseBuiltIn { component: kind };
        match refused_without_change(&mut sys, &back, "putting the built-in back", false)? {
            Some(why) if inactive => {
                return Err(format!(
                    "the script is Inactive, yet putting the built-in back was refused: {why}"
                ));
            }
            Some(_) => {}
            None if sys.wiring().script(kind).is_some() => {
                return Err(
                    "the built-in was put back, but the script is still in its place".to_owned(),
                );
            }
            None => {}
        }
        let _ = sys.apply(&Input::ActivateAll);
        run_ticks(&mut sys, 20, None, ticks)?;
        Ok(())
    }
}

impl Target for Scripts {
    fn name(&self) -> &'static str {
        "script"
    }

    fn seeds(&self) -> &[Case] {
        &self.seeds
    }

    fn generate(&self, rng: &mut Rng) -> Case {
        if !self.seeds.is_empty() && rng.chance(0.5) {
            let seed = rng.pick(&self.seeds).text(0);
            let mut tokens = tokenize(&seed);
            for _ in 0..=rng.below(4) {
                mutate_tokens(&mut tokens, rng);
            }
            Case::one(tokens.concat())
        } else if rng.chance(0.1) {
            Case::one(junk(rng))
        } else {
            Case::one(random_script(rng))
        }
    }

    fn run(&mut self, case: &Case) -> Result<(), String> {
        let text = case.text(0);
        match Program::compile("fuzz.rhai", &text) {
            Err(e) => {
                check_error(&e)?;
                self.systems()?.refuse_broken(&text)
            }
            Ok(program) => self.systems()?.load_and_run(&text, &program),
        }
    }

    fn alloc_bound(&self, case: &Case) -> u64 {
        // Three copies of open_field's system (the set-up's, the input's, its checkpoint's:
        // 8 MiB at the peak in practice), the engine's values (the strings of one value 64 KiB
        // in all, 10 000 array items, 1 000 map entries), and the parse tree in proportion to
        // the text.
        (64 << 20) + 256 * case.len() as u64
    }
}

/// An error must say what went wrong, briefly.
fn check_error(e: &ScriptError) -> Result<(), String> {
    let text = e.to_string();
    if e.message().trim().is_empty() {
        return Err(format!("an error without a message: {text:?}"));
    }
    let chars = text.chars().count();
    if chars > ERROR_CHARS {
        let shown: String = text.chars().take(200).collect();
        return Err(format!(
            "an error of {chars} characters (at most {ERROR_CHARS}): {shown}…"
        ));
    }
    Ok(())
}

// ------------------------------------------------------------------ token mutations

/// `text` cut into tokens — words, numbers, strings, comments, runs of blanks, single
/// punctuation — whose concatenation is `text`.
pub fn tokenize(text: &str) -> Vec<String> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let start = i;
        i += 1;
        if c.is_alphanumeric() || c == '_' {
            while i < chars.len()
                && (chars[i].is_alphanumeric()
                    || chars[i] == '_'
                    || chars[i] == '.' && c.is_ascii_digit())
            {
                i += 1;
            }
        } else if c.is_whitespace() {
            while i < chars.len() && chars[i].is_whitespace() {
                i += 1;
            }
        } else if c == '"' || c == '`' {
            while i < chars.len() && chars[i] != c {
                i += 1;
            }
            i = (i + 1).min(chars.len());
        } else if c == '/' && chars.get(i) == Some(&'/') {
            while i < chars.len() && chars[i] != '\n' {
                i += 1;
            }
        }
        out.push(chars[start..i].iter().collect());
    }
    out
}

/// Words and punctuation of the language, and names of the component's.
const VOCABULARY: &[&str] = &[
    "fn",
    "let",
    "const",
    "if",
    "else",
    "while",
    "loop",
    "for",
    "in",
    "return",
    "break",
    "continue",
    "throw",
    "try",
    "catch",
    "switch",
    "do",
    "until",
    "this",
    "rtc",
    "true",
    "false",
    "()",
    "(",
    ")",
    "{",
    "}",
    "[",
    "]",
    "#{",
    ",",
    ";",
    ":",
    ".",
    "..",
    "..=",
    "=",
    "==",
    "!=",
    "+",
    "-",
    "*",
    "/",
    "%",
    "<<",
    ">>",
    "&",
    "|",
    "^",
    "!",
    "&&",
    "||",
    "+=",
    "-=",
    "?.",
    "??",
    "=>",
    "|x|",
    "Fn",
    "call",
    "curry",
    "eval",
    "print",
    "debug",
    "type_of",
    "is_def_var",
    "on_execute",
    "on_initialize",
    "on_activated",
    "on_error",
    "on_reset",
    "COMPONENT",
    "read",
    "write",
    "is_new",
    "clear",
    "param",
    "tm",
    "period",
    "index",
    "time",
    "sec",
    "nsec",
    "data",
    "points",
    "vx",
    "vy",
    "w",
    "x",
    "y",
    "theta",
    "len",
    "push",
    "pad",
    "sin",
    "atan2",
    "hypot",
    "sqrt",
    "pow",
    "to_int",
    "to_float",
    "wrap_angle",
    "PI",
    "1e308",
    "-0.0",
    "0.0 / 0.0",
    "\"MotorControl\"",
    "\"DriveControl\"",
    "\"\"",
    "`${this}`",
    "'a'",
];

/// Statements that test the bounds and the ports, to put into an action.
const STATEMENTS: &[&str] = &[
    "loop {}",
    "while true { }",
    "loop { this.n = 1; }",
    "for i in 0..9223372036854775807 { }",
    "for i in 0..150000 { }",
    "for i in 0..40000 { let a = i * 2; }",
    "let s = \"ab\"; loop { s += s; }",
    "let s = \"x\"; for i in 0..20 { s += s; } this.s = s;",
    "let a = []; loop { a.push(1); }",
    "let a = []; a.pad(100000, 0.0);",
    "let a = [1]; for i in 0..30 { a += a; }",
    "let a = []; for i in 0..9000 { a.push([i]); } this.a = a;",
    "let m = #{}; for i in 0..5000 { m[`k${i}`] = i; }",
    "this.me = this;",
    "this.me = this; this.me2 = this;",
    "let a = [1, 2]; a.push(a); a.push(a); a.push(a); this.a = a;",
    "let n = 0; this.count = || { n += 1; n };",
    "if this.count != () { let c = this.count.call(); this.c = c; }",
    "if type_of(this.count) != \"Fn\" { let n = 0; this.count = || { n += 1; n }; } this.c = this.count.call();",
    "if type_of(this.count) != \"Fn\" { let n = 0; this.count = || { n += 1; n }; } rtc.torque.write(#{ tm: rtc.tm, data: [0.0, 0.01 * this.count.call()] });",
    "fn_rec(0);",
    "throw \"boom\";",
    "throw this;",
    "throw #{ a: 1 };",
    "let x = 1 / 0;",
    "let x = 9223372036854775807 + 1;",
    "let x = -9223372036854775808 / -1;",
    "let x = to_int(1e300);",
    "let x = sqrt(-1.0); this.x = x;",
    "let x = \"abc\".sub_string(5, 9223372036854775807);",
    "let x = [1, 2, 3][9223372036854775807];",
    "let x = \"abc\"[-100];",
    "for i in 0..1000 { print(i); }",
    "print(this); debug(rtc);",
    "this.rtc = rtc;",
    "this.port = rtc.torque;",
    "if this.port != () { this.port.write(#{ tm: rtc.tm, data: [0.0, 0.0] }); }",
    "if this.rtc != () { this.rtc.torque.write(#{ tm: rtc.tm, data: [0.0] }); }",
    "let x = rtc.no_such_port;",
    "let x = rtc.in_control_points.read();",
    "let x = rtc.target_velocity.read();",
    "let x = rtc.torque.read();",
    "rtc.in_current_wheel_angle.write(#{ tm: rtc.tm, data: [] });",
    "rtc.torque.write(#{ tm: rtc.tm, data: [0.0 / 0.0, 1e308 * 10.0] });",
    "rtc.torque.write(#{ tm: rtc.tm, data: [] });",
    "rtc.torque.write(#{ data: [1.0, 1.0] });",
    "rtc.torque.write(#{ tm: #{ sec: -1, nsec: 2000000000 }, data: [1.0, 1.0] });",
    "rtc.torque.write(#{ tm: rtc.tm, data: [5.0, -5.0, 1e300, 7] });",
    "rtc.torque.write(42);",
    "let d = []; d.pad(9000, 1.0); rtc.torque.write(#{ tm: rtc.tm, data: d });",
    "rtc.target_velocity.write(#{ tm: rtc.tm, vx: 1e308, vy: 0.0, w: -1e308 });",
    "rtc.target_velocity.write(#{ tm: rtc.tm, vx: 0.0 / 0.0, vy: 0.0, w: 0.0 });",
    "rtc.target_velocity.write(#{ tm: rtc.tm, vx: 0.3, vy: 0.0, w: 0.2 });",
    "rtc.target_velocity.write(#{ tm: rtc.tm, vx: \"fast\", vy: (), w: [] });",
    "rtc.out_deviating.write(#{ tm: rtc.tm, data: 1e308 });",
    "rtc.safety_stop.write(#{ tm: rtc.tm, data: 1.0 });",
    "let p = rtc.param(\"NoSuchParameter\");",
    "let p = rtc.param(\"\");",
    "rtc.tm = 5;",
    "this = 5;",
    "let f = Fn(\"on_execute\"); f.call(rtc);",
    "on_execute(rtc);",
    "let x = eval(\"loop {}\");",
    "let x = eval(\"fn on_execute(rtc) { loop {} } 1\");",
    "let x = `${`${`${`${this}`}`}`}`;",
    "let x = switch rtc.index { 0 => 1, _ => 2 };",
    "let x = rtc?.tm?.sec ?? 0;",
    "let x = range(0, 100000000, 1); for i in x { }",
    "let t = rtc.tm; t.sec = 9223372036854775807; this.t = t;",
    "let x = rtc.period * 1e308;",
    "do { this.k = 1; } until false;",
    "let x = \"é漢😀\".to_upper(); let y = x[1]; this.y = y;",
];

/// One hostile statement.
fn statement(rng: &mut Rng) -> String {
    match rng.below(12) {
        0 => {
            // A port read of the component's, or a write of a value it may not take.
            let port = *rng.pick(&PORTS);
            match rng.below(4) {
                0 => format!("if rtc.{port}.is_new() {{ this.{port} = rtc.{port}.read(); }}"),
                1 => format!("let v = rtc.{port}.read();"),
                2 => format!("rtc.{port}.clear();"),
                _ => format!(
                    "rtc.{port}.write(#{{ tm: rtc.tm, data: [{}, {}], vx: {}, vy: 0.0, w: {} }});",
                    number(rng),
                    number(rng),
                    number(rng),
                    number(rng)
                ),
            }
        }
        1 => {
            let names = param_names();
            let name = if names.is_empty() {
                "x"
            } else {
                *rng.pick(&names)
            };
            format!("this.p = rtc.param(\"{name}\") * {};", number(rng))
        }
        // Mostly within the parser's bounds (the script compiles), sometimes past them.
        2 => nested(rng),
        3 if rng.chance(0.3) => huge_literal(rng),
        _ => (*rng.pick(STATEMENTS)).to_owned(),
    }
}

/// Every in- and out-port of the two places, as a script names them.
const PORTS: [&str; 12] = [
    "target_velocity",
    "in_current_wheel_angle",
    "in_simulated_position",
    "torque",
    "out_current_wheel_angle",
    "out_simulated_position_to_invent_gui",
    "out_simulated_position_to_localization",
    "in_control_points",
    "in_current_position",
    "out_deviating",
    "safety_stop",
    "nothing",
];

/// The parameters of the two places.
fn param_names() -> Vec<&'static str> {
    MotorControlParams::SPECS
        .iter()
        .chain(DriveControlParams::SPECS.iter())
        .map(|s| s.name)
        .collect()
}

/// A number as text, often hostile.
fn number(rng: &mut Rng) -> String {
    let n = rng.pick(INTERESTING_NUMBERS);
    if n.is_empty() || n.contains('_') || n.starts_with("0x") {
        "1.5".to_owned()
    } else if n.parse::<i64>().is_ok() {
        n.to_string()
    } else if n.parse::<f64>().is_ok_and(f64::is_finite) && !n.contains('.') && !n.contains('e') {
        format!("{n}.0")
    } else {
        (*rng.pick(&[
            "1e308",
            "(0.0 / 0.0)",
            "(1e308 * 10.0)",
            "-1e308",
            "5e-324",
            "0.5",
        ]))
        .to_owned()
    }
}

/// Deep nesting: parentheses, blocks, `if`s, arrays, maps, calls, unary minus, strings.
fn nested(rng: &mut Rng) -> String {
    let depth = match rng.below(10) {
        0 => 1000 + rng.index(20_000),
        1..=2 => 40 + rng.index(100),
        _ => 2 + rng.index(30),
    };
    let (open, mid, close) = *rng.pick(&[
        ("(", "1", ")"),
        ("{ ", "1", " }"),
        ("if true { ", "this.n = 1;", " }"),
        ("[", "1", "]"),
        ("#{a: ", "1", "}"),
        ("sin(", "0.5", ")"),
        ("-", "1", ""),
        ("!", "true", ""),
        ("`${", "1", "}`"),
        ("|| ", "1", ""),
        ("loop { ", "break;", " }"),
    ]);
    format!(
        "let deep = {}{mid}{};",
        open.repeat(depth),
        close.repeat(depth)
    )
}

/// A huge literal: a string, a number, a name, a comment, many statements.
fn huge_literal(rng: &mut Rng) -> String {
    let n = if rng.chance(0.3) {
        70_000 + rng.index(100_000)
    } else {
        100 + rng.index(5000)
    };
    match rng.below(7) {
        0 => format!("let s = \"{}\";", "x".repeat(n)),
        1 => format!("let s = `{}`;", "é".repeat(n / 2)),
        2 => format!("let x = {};", "9".repeat(n)),
        3 => format!("let x = 0.{}e{};", "1".repeat(n), "9".repeat(1 + n % 20)),
        4 => format!("let {} = 1;", "a".repeat(n)),
        5 => format!("/* {} */", "/*".repeat(n / 4)),
        _ => "this.n = 1;\n".repeat(n / 10),
    }
}

/// Random tokens.
fn junk(rng: &mut Rng) -> String {
    let n = 1 + rng.index(300);
    let mut s = String::new();
    for _ in 0..n {
        s.push_str(rng.pick::<&str>(VOCABULARY));
        s.push(*rng.pick(&[' ', ' ', '\n', '\t']));
    }
    s
}

/// A whole script made from scratch: a declaration (often right, sometimes wrong), helper
/// functions, some of the actions (now and then with parameters a component cannot give),
/// each a few statements.
pub fn random_script(rng: &mut Rng) -> String {
    let mut s = String::new();
    match rng.below(10) {
        0..=3 => s.push_str("const COMPONENT = \"MotorControl\";\n"),
        4..=7 => s.push_str("const COMPONENT = \"DriveControl\";\n"),
        8 => {
            let name = *rng.pick(&["Localization", "", "motorcontrol", "MotorControl ", "é"]);
            let _ = writeln!(s, "const COMPONENT = \"{name}\";");
        }
        _ => {}
    }
    if rng.chance(0.3) {
        s.push_str("fn fn_rec(n) { fn_rec(n + 1) }\n");
    }
    if rng.chance(0.2) {
        s.push_str("fn twice(f, x) { f.call(f.call(x)) }\n");
    }
    let actions = rtnav::script::ACTIONS;
    for _ in 0..1 + rng.below(6) {
        let action = if rng.chance(0.9) {
            *rng.pick(&actions)
        } else {
            *rng.pick(&["on_exec", "On_Execute", "main", "on_execute_"])
        };
        let params = match rng.below(40) {
            0..=3 => "",
            4 => "rtc, extra",
            _ => "rtc",
        };
        let _ = writeln!(s, "fn {action}({params}) {{");
        for _ in 0..1 + rng.below(4) {
            let _ = writeln!(s, "    {}", statement(rng));
        }
        s.push_str("}\n");
    }
    if rng.chance(0.1) {
        let _ = writeln!(s, "{}", statement(rng));
    }
    s
}

/// One token-level change of `tokens`.
pub fn mutate_tokens(tokens: &mut Vec<String>, rng: &mut Rng) {
    if tokens.is_empty() {
        tokens.push(String::new());
    }
    let len = tokens.len();
    let i = rng.index(len);
    match rng.below(10) {
        // Drop one.
        0 => {
            tokens.remove(i);
        }
        // Repeat one (a bracket thousands of times: deep nesting).
        1 => {
            let times = if rng.chance(0.2) {
                1 + rng.index(5000)
            } else {
                2
            };
            let t = tokens[i].repeat(times);
            tokens[i] = t;
        }
        // Swap two.
        2 => {
            let j = rng.index(len);
            tokens.swap(i, j);
        }
        // Replace one with a word of the language.
        3 => tokens[i] = (*rng.pick(VOCABULARY)).to_owned(),
        // Replace one with another of the script's (a port's name with another's, …).
        4 => tokens[i] = tokens[rng.index(len)].clone(),
        // A number replaced with a hostile one.
        5 => {
            let numbers: Vec<usize> = (0..len)
                .filter(|&k| tokens[k].starts_with(|c: char| c.is_ascii_digit()))
                .collect();
            if !numbers.is_empty() {
                let k = *rng.pick(&numbers);
                tokens[k] = number(rng);
            }
        }
        // Wrap a stretch in a loop.
        6 => {
            let j = (i + 1 + rng.index(40)).min(len);
            let head = *rng.pick(&["loop { ", "while true { ", "for q in 0..100000 { "]);
            tokens.insert(j, " }".to_owned());
            tokens.insert(i, head.to_owned());
        }
        // A hostile statement put after a `{` or a `;` (inside an action, mostly).
        _ => {
            let places: Vec<usize> = (0..len)
                .filter(|&k| tokens[k] == "{" || tokens[k] == ";")
                .collect();
            let at = if places.is_empty() {
                i
            } else {
                *rng.pick(&places) + 1
            };
            tokens.insert(at, format!(" {} ", statement(rng)));
        }
    }
}
