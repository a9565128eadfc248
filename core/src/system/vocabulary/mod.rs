//! The vocabulary: the words every part of the system speaks — which component
//! ([`ComponentKind`](kind::ComponentKind)), at what rates ([`Rates`](rates::Rates)), a
//! request ([`Input`](input::Input)), a fact ([`EventKind`](events::EventKind),
//! [`SystemEvent`](events::SystemEvent)), the system's errors, the one reader of JSON
//! texts and the longest run there is.
//!
//! It may use: the crate outside `system/` (`rtc`, `map`, `motion`, `interfaces`, `reason`,
//! `present`) — nothing else of `system/`.
//! Used by: every layer above it (`simulation`, `runs`, `sessions`).

pub(super) mod error;
pub(super) mod events;
pub(super) mod input;
pub(super) mod json_text;
pub(super) mod kind;
pub(super) mod rates;
pub(super) mod run_limit;
