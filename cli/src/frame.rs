//! A system's frame written as PNG (`--png` of `run` and `replay`).

use std::path::Path;

use rtnav::render::{Layers, Renderer, caption};
use rtnav::system::System;
use rtnav_cli::error::{CliError, CliResult};

/// Draws `system` at `size` with every layer and its caption, and writes it to `path`.
pub fn write_png(system: &System, size: (u32, u32), path: &Path) -> CliResult<()> {
    let mut renderer = Renderer::new(size.0, size.1).map_err(CliError::core)?;
    let frame = renderer
        .render_system(system, &caption(system), Layers::ALL)
        .map_err(CliError::core)?;
    write_bytes(path, &frame.encode_png().map_err(CliError::core)?)
}

/// Writes `bytes` to `path`.
pub fn write_bytes(path: &Path, bytes: &[u8]) -> CliResult<()> {
    std::fs::write(path, bytes).map_err(|source| CliError::Write {
        path: path.to_path_buf(),
        source,
    })
}
