//! Whether a scenario needs the external data ([`crate::data`]): a tool that has to skip
//! such a scenario when the data is absent asks before it sets the scenario up.

use crate::data::data_relative;
use crate::system::{FileResolver, MapSource, Scenario};

/// The file a scenario names for its map: the JSON or MovingAI map, a ROS map's YAML.
pub fn map_file(scenario: &Scenario) -> &str {
    match &scenario.map {
        MapSource::Json { path } | MapSource::Movingai { path, .. } => path,
        MapSource::Ros { yaml, .. } => yaml,
    }
}

/// Whether one of the files of `scenario`'s map is in the external data: every file the map
/// needs ([`Scenario::map_files`], read through `resolver`) or, when those cannot be listed
/// (a ROS map's YAML that cannot be read), the file the scenario names ([`map_file`]).
pub fn needs_external_data(scenario: &Scenario, resolver: &dyn FileResolver) -> bool {
    match scenario.map_files(resolver) {
        Ok(files) => files.iter().any(|f| data_relative(f).is_some()),
        Err(_) => data_relative(map_file(scenario)).is_some(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::system::MemoryResolver;

    fn scenario(map: serde_json::Value) -> Scenario {
        let json = serde_json::json!({
            "name": "s", "description": "", "lesson": "", "map": map,
            "start": {"x": 1.0, "y": 1.0}, "goal": {"x": 2.0, "y": 2.0},
            "time_limit": 10, "expect": {"outcome": "arrived"}
        });
        Scenario::from_json(&json.to_string()).expect("a valid scenario")
    }

    #[test]
    fn a_map_of_the_repository_needs_no_data() {
        let s = scenario(serde_json::json!({"format": "json", "path": "fixtures/maps/a.json"}));
        assert_eq!(map_file(&s), "fixtures/maps/a.json");
        assert!(!needs_external_data(&s, &MemoryResolver::new()));
    }

    #[test]
    fn a_map_of_the_data_needs_it_even_when_it_cannot_be_read() {
        let s = scenario(serde_json::json!({
            "format": "ros", "yaml": "../shared/data/rosmaps/office.yaml"
        }));
        assert_eq!(map_file(&s), "../shared/data/rosmaps/office.yaml");
        assert!(needs_external_data(&s, &MemoryResolver::new()));
        let s = scenario(serde_json::json!({
            "format": "movingai", "path": "../shared/data/movingai/dao/arena.map",
            "grid_size": 0.5
        }));
        assert!(needs_external_data(&s, &MemoryResolver::new()));
    }

    #[test]
    fn a_ros_image_in_the_data_is_found_through_the_yaml() {
        let s = scenario(serde_json::json!({"format": "ros", "yaml": "maps/office.yaml"}));
        let yaml = "image: ../../shared/data/rosmaps/office.pgm\nresolution: 0.1\n\
                    origin: [0.0, 0.0, 0.0]\nnegate: 0\noccupied_thresh: 0.65\n\
                    free_thresh: 0.196\n";
        let files = MemoryResolver::new().with("maps/office.yaml", yaml.as_bytes().to_vec());
        assert!(needs_external_data(&s, &files));
    }
}
