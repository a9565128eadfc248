//! The local path by descent (000 §5.2.4.10, spec §3 step 5).

use super::potential_field::{CellState, PotentialField};
use crate::errors::LocalPathError;
use crate::map::Cell;

/// The local path from `from` (the current cell) to the field's target: repeatedly step to
/// the 8-neighbour with the lowest potential that is lower than the current one, until the
/// target (000 §5.2.4.10).
///
/// Only reached cells are candidates (impassable cells have potential 0 and are ignored,
/// as are cells the field never reached), and a diagonal step may not cut the corner of an
/// impassable cell. **Decision (spec §3 step 5)**: "lower" compares the key
/// `(potential, finalization order)` of [`PotentialField::key`], so equal potentials cannot
/// stall the descent: every reached cell but the target has a lower neighbour (its parent),
/// and the keys strictly decrease, so the descent ends at the target.
///
/// It is the chain of parents, and is computed as such: a cell's parent is finalized before
/// any other neighbour the step to which is allowed (else that neighbour would have
/// assigned the cell first), so it has the lowest key among them; and a neighbour not
/// finalized (the frontier of a stopped field) was queued at or above the parent's
/// potential, and ranks after every finalized cell. (`tests/local_path_planning_field.rs`
/// compares it with the search over the neighbours' keys.)
///
/// Errors: [`LocalPathError::NoRoute`] if `from` was not reached.
pub fn descend(field: &PotentialField, from: Cell) -> Result<Vec<Cell>, LocalPathError> {
    let Some(request) = field.request() else {
        return Err(LocalPathError::NoRoute {
            target: from,
            current: from,
        });
    };
    let target = request.target;
    let no_route = LocalPathError::NoRoute {
        target,
        current: from,
    };
    if field.state(from) != CellState::Reached {
        return Err(no_route);
    }
    let mut path = vec![from];
    let mut cell = from;
    while cell != target {
        if path.len() > field.reached_count() {
            return Err(no_route);
        }
        let Some(parent) = field.parent(cell) else {
            return Err(no_route);
        };
        path.push(parent);
        cell = parent;
    }
    Ok(path)
}
