//! Local path planning algorithms of seed 000: potential field, descent, merge, control
//! points (SPEC §3).
