//! A scenario's content hash: what a replay records of the scenario it was made on, so that a
//! replay of a scenario that has changed since is refused with that reason (spec §6,
//! Decision 0.3, hand-ins stay valid) instead of being judged against something else.
//!
//! SHA-256, as lowercase hex, over the scenario as read — its canonical JSON (serde_json of
//! the parsed [`Scenario`]: the keys in declaration order, numbers shortest round-trip, so a
//! file's layout, key order and number spelling do not count, only what it says) — and then
//! every file its map needs ([`Scenario::map_files`]), each its path and its bytes. Each part
//! is preceded by its length in bytes (8, little-endian), so no two contents hash alike by
//! shifting bytes from one part to the next.

use sha2::{Digest, Sha256};

use super::scenario::{FileResolver, Scenario};
use crate::system::simulation::telemetry::hex;

/// What the hash starts with (its scheme; a new scheme takes a new tag).
const TAG: &[u8] = b"rtnav-scenario-content-1";

fn part(hasher: &mut Sha256, bytes: &[u8]) {
    hasher.update((bytes.len() as u64).to_le_bytes());
    hasher.update(bytes);
}

impl Scenario {
    /// The scenario's content hash (module documentation), its map files read through
    /// `resolver`.
    pub fn content_hash(&self, resolver: &dyn FileResolver) -> crate::Result<String> {
        let json =
            serde_json::to_string(self).map_err(|e| crate::errors::ScenarioError::Scenario {
                scenario: crate::present::excerpt(&self.name),
                reason: format!("cannot be written as JSON: {e}"),
            })?;
        let mut hasher = Sha256::new();
        part(&mut hasher, TAG);
        part(&mut hasher, json.as_bytes());
        for path in self.map_files(resolver)? {
            part(&mut hasher, path.as_bytes());
            part(&mut hasher, &resolver.read(&path)?);
        }
        Ok(hex(&hasher.finalize()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::system::runs::scenario::MemoryResolver;

    const SCENARIO: &str = r#"{"name": "tiny", "description": "", "lesson": "",
        "map": {"format": "json", "path": "m.json"},
        "start": {"x": 0.5, "y": 0.5}, "goal": {"x": 2.5, "y": 0.5},
        "time_limit": 30, "expect": {"outcome": "arrived"}}"#;
    const MAP: &str = r#"{"width": 4, "height": 2, "grid_size": 1.0, "rows": ["....", "...."]}"#;

    fn hash(scenario: &str, map: &str) -> String {
        let files = MemoryResolver::new().with("m.json", map.as_bytes().to_vec());
        Scenario::from_json(scenario)
            .unwrap()
            .content_hash(&files)
            .unwrap()
    }

    #[test]
    fn the_hash_follows_what_the_scenario_and_its_map_say_not_their_layout() {
        let h = hash(SCENARIO, MAP);
        assert_eq!(h.len(), 64);
        assert!(h.bytes().all(|b| b.is_ascii_hexdigit()));
        // The same content written otherwise: the same hash.
        let relaid = SCENARIO
            .replace("\"x\": 2.5", "\"x\":2.50")
            .replace('\n', " ");
        assert_eq!(hash(&relaid, MAP), h);
        // Another goal, another map cell: another hash.
        assert_ne!(hash(&SCENARIO.replace("2.5", "3.5"), MAP), h);
        assert_ne!(hash(SCENARIO, &MAP.replace("....\"]", "..#.\"]")), h);
    }

    #[test]
    fn a_missing_map_file_is_an_error() {
        let s = Scenario::from_json(SCENARIO).unwrap();
        assert!(s.content_hash(&MemoryResolver::new()).is_err());
    }
}
