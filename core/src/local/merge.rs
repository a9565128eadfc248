//! Merging the local path with the rest of the held path (000 §5.2.4.11, spec §3 step 6).

use crate::map::Cell;

/// The merged path: `local` (current cell … target) followed by the held path after the
/// target up to the goal, `held[target_index + 1 ..= goal_index]`, so the target is not
/// repeated. Indices past the end are clamped.
pub fn merge_paths(
    local: &[Cell],
    held: &[Cell],
    target_index: usize,
    goal_index: usize,
) -> Vec<Cell> {
    let end = goal_index.saturating_add(1).min(held.len());
    let start = target_index.saturating_add(1).min(end);
    let mut merged = Vec::with_capacity(local.len() + end - start);
    merged.extend_from_slice(local);
    merged.extend_from_slice(&held[start..end]);
    merged
}
