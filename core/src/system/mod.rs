//! The whole system: every component wired as in SPEC §0, in one execution context.
