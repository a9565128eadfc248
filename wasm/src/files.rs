//! [`Files`]: bytes the page hands over — a scenario's map files (fetched from the server) or
//! the files a user picked — held as the core's [`PickedFiles`].

use rtnav::system::PickedFiles;
use wasm_bindgen::prelude::*;

/// Named files in memory: paths as a scenario writes them (`fixtures/maps/…`), or the
/// names of the files a user picked.
#[wasm_bindgen]
#[derive(Debug, Clone, Default)]
pub struct Files(pub(crate) PickedFiles);

#[wasm_bindgen]
impl Files {
    /// No files.
    #[wasm_bindgen(constructor)]
    pub fn new() -> Files {
        Files::default()
    }

    /// Adds (or replaces) a file.
    pub fn add(&mut self, path: &str, bytes: Vec<u8>) {
        self.0.add(path, bytes);
    }

    /// How many files there are.
    pub fn len(&self) -> usize {
        self.0.len()
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }
}
