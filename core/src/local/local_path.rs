//! The local path by descent (000 §5.2.4.10, spec §3 step 5).

use super::potential_field::{CellState, NEIGHBOURS, PotentialField};
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
/// and the keys strictly decrease, so the descent ends at the target. It is in fact the
/// chain of parents.
///
/// Errors: [`LocalPathError::NoRoute`] if `from` was not reached (or has no lower
/// neighbour, which a field made by [`PotentialField::compute`] never gives).
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
    let Some(mut key) = field.key(from) else {
        return Err(no_route);
    };
    let mut path = vec![from];
    let mut cell = from;
    while cell != target {
        if path.len() > field.reached_count() {
            return Err(no_route);
        }
        let (x, y) = (cell.0 as i64, cell.1 as i64);
        let mut best: Option<(Cell, (f64, u32))> = None;
        for &(dx, dy) in &NEIGHBOURS {
            let (nx, ny) = (x + dx, y + dy);
            if nx < 0 || ny < 0 {
                continue;
            }
            let n = (nx as usize, ny as usize);
            let Some(k) = field.key(n) else { continue };
            if dx != 0
                && dy != 0
                && (field.state(((x + dx) as usize, y as usize)) == CellState::Impassable
                    || field.state((x as usize, (y + dy) as usize)) == CellState::Impassable)
            {
                continue;
            }
            if less(k, key) && best.is_none_or(|(_, b)| less(k, b)) {
                best = Some((n, k));
            }
        }
        let Some((n, k)) = best else {
            return Err(no_route);
        };
        path.push(n);
        cell = n;
        key = k;
    }
    Ok(path)
}

fn less(a: (f64, u32), b: (f64, u32)) -> bool {
    a.0 < b.0 || (a.0 == b.0 && a.1 < b.1)
}
