//! Untrusted text (spec §6, Decision 0.3): every reader of a person's text — scenario, replay
//! and share-link JSON, `.conf` files and bundles, the map formats (rtnav JSON, ROS YAML and
//! its PGM image, MovingAI `.map` and `.scen`) — answers any string with a value or a named
//! error, never a panic, and a short error.
//!
//! The strings are arbitrary (any Unicode), made of the pieces the formats are built of mixed
//! with multi-byte characters, and the project's own files cut at a random character with a
//! multi-byte character and anything after it — so an error falls on, inside or just after a
//! character of 2, 3 or 4 bytes.

use std::path::Path;

use base64::Engine as _;
use proptest::prelude::*;
use rtnav::map::formats::{json, movingai, ros};
use rtnav::rtc::ConfFile;
use rtnav::system::{Input, Rates, Replay, Scenario, Session, System};

fn root() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
}

fn file(path: &str) -> String {
    std::fs::read_to_string(root().join(path)).unwrap()
}

/// The project's files that each reader reads, to cut and splice.
fn fixtures() -> Vec<String> {
    [
        "fixtures/scenarios/open_field.json",
        "fixtures/scenarios/ex_fault_recovery.json",
        "fixtures/replays/ex_fault_recovery.solution.rtnav.json",
        "fixtures/maps/corridor.json",
        "fixtures/maps/tiny.yaml",
        "fixtures/maps/yard.map",
        "fixtures/conf/LocalPathPlanning.conf",
    ]
    .iter()
    .map(|p| file(p))
    .collect()
}

const PIECES: &[&str] = &[
    "\"",
    "{",
    "}",
    "[",
    "]",
    ":",
    ",",
    " ",
    "\n",
    "\r\n",
    "\t",
    "#",
    "NaN",
    "-Infinity",
    "nul",
    "tru",
    "1e400",
    "0.5",
    "-1",
    "é",
    "ü",
    "あ",
    "漢",
    "😀",
    "𝕏",
    "\u{301}",
    "\u{feff}",
    "\u{2028}",
    "\u{fffd}",
    "\"name\"",
    "\"format\"",
    "\"rtnav-replay\"",
    "\"version\": 2",
    "\"v\": 1",
    "\"scenario\"",
    "\"width\"",
    "conf.default.dmin: ",
    "# [LocalPathPlanning0]\n",
    "image: ",
    "origin: [",
    "resolution: ",
    "P5\n",
    "P2\n",
    "4 2\n255\n",
    "type octile\n",
    "height 4\n",
    "width 5\n",
    "map\n",
    "version 1\n",
    "- ",
    "&a ",
    "*a",
];

/// Arbitrary strings that reach the readers' edges (module documentation).
fn text() -> impl Strategy<Value = String> {
    let piece = prop_oneof![
        3 => proptest::sample::select(PIECES).prop_map(str::to_owned),
        1 => "\\PC{0,6}",
        1 => any::<char>().prop_map(String::from),
    ];
    let cut = (
        proptest::sample::select(fixtures()),
        any::<proptest::sample::Index>(),
        proptest::sample::select(PIECES),
        "\\PC{0,4}",
    )
        .prop_map(|(f, at, piece, tail)| {
            let chars: Vec<char> = f.chars().collect();
            let head: String = chars[..at.index(chars.len() + 1)].iter().collect();
            format!("{head}{piece}{tail}")
        });
    prop_oneof![
        2 => prop::collection::vec(piece, 0..24).prop_map(|v| v.concat()),
        2 => cut,
        1 => any::<String>(),
    ]
}

/// What an error may say at most \[characters\]: the excerpt and message bounds, a line and
/// a reason around them.
const LONGEST_ERROR: usize = 1200;

fn short<T, E: std::fmt::Display>(r: Result<T, E>) -> Result<(), TestCaseError> {
    if let Err(e) = r {
        let n = e.to_string().chars().count();
        prop_assert!(n <= LONGEST_ERROR, "an error of {n} characters: {e}");
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn the_system_s_json_readers_never_panic(t in text()) {
        short(Scenario::from_json(&t))?;
        short(Replay::from_json(&t))?;
        short(Replay::scenario_of(&t))?;
        // A share link: the token as pasted, and a token made of this text as its set-up.
        short(Session::decode_token(&t))?;
        let token = base64::engine::general_purpose::URL_SAFE_NO_PAD
            .encode(miniz_oxide::deflate::compress_to_vec(t.as_bytes(), 6));
        short(Session::decode_token(&token))?;
        short(Session::share_scenario(&token))?;
    }

    #[test]
    fn the_conf_readers_never_panic(t in text()) {
        short(ConfFile::parse(&t))?;
    }

    #[test]
    fn the_map_readers_never_panic(t in text()) {
        short(json::load(&t))?;
        short(ros::parse_yaml(&t))?;
        short(movingai::load_map(&t))?;
        short(movingai::load_scen(&t))?;
        // The text as a map_server YAML with a PGM, and as the PGM (its header) of a YAML.
        let pgm = b"P5\n4 2\n255\n\0\0\0\0\xff\xff\xff\xff";
        short(ros::load(&t, pgm, &ros::RosLoadOptions::default()))?;
        let yaml = file("fixtures/maps/tiny.yaml");
        short(ros::load(&yaml, t.as_bytes(), &ros::RosLoadOptions::default()))?;
    }
}

proptest! {
    // A system per case: fewer cases.
    #![proptest_config(ProptestConfig { cases: 48, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn the_conf_bundle_reader_never_panics(t in text()) {
        let mut system = System::new(Rates::default()).unwrap();
        short(system.apply(&Input::LoadConf { text: t }))?;
    }
}

/// The inputs that once panicked, named.
#[test]
fn the_inputs_that_once_panicked_are_named_errors() {
    for t in ["\"é", "\"あ", "\"😀", "{\"x\": nulé}", "\u{feff}\"é"] {
        let e = Scenario::from_json(t).unwrap_err();
        assert!(
            e.to_string().starts_with("scenario `(JSON)`: "),
            "{t:?}: {e}"
        );
        assert!(Replay::from_json(t).is_err());
        let token = base64::engine::general_purpose::URL_SAFE_NO_PAD
            .encode(miniz_oxide::deflate::compress_to_vec(t.as_bytes(), 6));
        assert!(Session::decode_token(&token).is_err());
    }
}
