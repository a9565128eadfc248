//! Shared helpers for the whole-system tests (native and wasm32).
