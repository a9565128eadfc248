//! `rtnav-wasm`: the browser's handle over `rtnav` (no logic of its own).
