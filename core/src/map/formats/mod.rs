//! Map file formats, each read from text or bytes (no filesystem: the core also runs in the
//! browser) into a valid [`GridMap`](super::GridMap) (spec §2, §5 "MapBuilder").
//!
//! | module | format |
//! | --- | --- |
//! | [`json`] | rtnav's own JSON map: size, `grid_size`, `origin` and the cells as rows of text |
//! | [`ros`] | ROS `map_server` maps: a YAML file and a PGM/PNG image |
//! | [`movingai`] | the MovingAI grid benchmark's `.map` and `.scen` files |
//!
//! A text file may start with a UTF-8 byte-order mark; each text reader skips one.
//!
//! Every loader checks its input completely and returns
//! [`MapError::Format`](crate::errors::MapError::Format) naming the format, the line (where
//! there is one) and the problem; nothing is half-loaded.
//!
//! The convenience functions that read files (`ros::load_file`, …) exist only off wasm32.

pub mod json;
pub mod movingai;
pub mod ros;
mod yaml_mapping;

// What an error message quotes of a file: `crate::present::excerpt`, the one helper.
use crate::present::excerpt as shown;

#[cfg(not(target_arch = "wasm32"))]
pub(crate) fn read_file(path: &std::path::Path) -> Result<Vec<u8>, crate::errors::MapError> {
    std::fs::read(path).map_err(|e| crate::errors::MapError::Io {
        path: path.display().to_string(),
        reason: e.to_string(),
    })
}
