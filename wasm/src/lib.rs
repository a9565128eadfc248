//! `rtnav-wasm`: the browser's handle over `rtnav` (no logic of its own: every call is one
//! call into the core's [`Session`](rtnav::system::Session) or its
//! [`Screen`](rtnav::render::Screen); `core/tests/tidy.rs` checks that nothing here reaches
//! past them).
//!
//! Long-lived state lives here, in Rust memory; JavaScript holds an opaque handle
//! ([`Demo`]: the session and its screen), owns the clock (`requestAnimationFrame`) and
//! calls [`Demo::step`] with the elapsed wall time, which becomes whole ticks of simulated
//! time (spec §6: components never read a clock). The frame is drawn into Rust memory and
//! shown by the page without a copy: a `Uint8ClampedArray` view at [`Demo::frame_ptr`] over
//! `memory.buffer` → `ImageData` → `putImageData` (the Rust and WebAssembly book's game of
//! life). Errors become JavaScript `Error`s only here ([`js`]), with the core's message and
//! the error as data (`detail`) for the page's words.
//!
//! Panics are bugs (spec §1), but a page must show one rather than freeze: the panic hook
//! installed at start-up records the message, which [`has_panicked`] and [`panic_message`]
//! report (the style of egui's `WebHandle`). They are free functions because after a panic
//! the handle that panicked stays borrowed and every further call on it throws.

use std::sync::Mutex;

use wasm_bindgen::prelude::*;

mod as_json;
mod demo;
mod files;
mod refusal;
mod replay;
mod system_view;
mod teach;

pub use demo::Demo;
pub use files::Files;
pub use replay::CompareView;

/// The first panic's message, recorded by the hook.
static PANIC_MESSAGE: Mutex<Option<String>> = Mutex::new(None);

/// Installs the panic hook (runs once, when the module is instantiated).
#[wasm_bindgen(start)]
pub fn start() {
    std::panic::set_hook(Box::new(|info| {
        let mut slot = PANIC_MESSAGE.lock().unwrap_or_else(|e| e.into_inner());
        if slot.is_none() {
            *slot = Some(info.to_string());
        }
        drop(slot);
        console_error_panic_hook::hook(info);
    }));
}

/// The core's package version (`rtnav::VERSION`), which the page shows.
#[wasm_bindgen]
pub fn version() -> String {
    rtnav::VERSION.to_owned()
}

/// Whether Rust code has panicked; after that the module must not be used any more.
#[wasm_bindgen]
pub fn has_panicked() -> bool {
    PANIC_MESSAGE
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .is_some()
}

/// The first panic's message and location, if Rust code has panicked.
#[wasm_bindgen]
pub fn panic_message() -> Option<String> {
    PANIC_MESSAGE
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .clone()
}

pub(crate) use refusal::{Msg, js, msg, refused, value};
