//! The LocalPath service's input checks (000 §3.2.2.1, spec §3 Decisions): a start or goal
//! must be clear of obstacles by `dmin`, a `GlobalPathCourse` must be a connected path of
//! cells inside the map. Each returns the checked value or the error that names the problem.

use super::LocalPathError;
use crate::map::{Cell, GridMap};

/// The cell of `(x, y)` if it and every cell within `dmin` are passable (000 §5.2.4.2);
/// `what` names the point in the error (`start`, `goal`).
pub fn clear_cell(
    map: &GridMap,
    what: &'static str,
    x: f64,
    y: f64,
    dmin: f64,
) -> Result<Cell, LocalPathError> {
    let cell = map
        .world_to_cell(x, y)
        .ok_or(LocalPathError::OutsideMap { what, x, y })?;
    if !map.is_clear(cell, dmin) {
        return Err(LocalPathError::NotClear {
            what,
            x,
            y,
            cell,
            distance: map.obstacle_distance(cell),
            dmin,
        });
    }
    Ok(cell)
}

/// The cells of `GlobalPathCourse(GridPathX, GridPathY, num)` (000 §3.2.2.1 (6)): both
/// arrays have `num` entries, `num` ≥ 1, every cell is in the map and consecutive cells are
/// 8-neighbours (spec §3 Decision).
pub fn course_cells(
    map: &GridMap,
    grid_path_x: &[i32],
    grid_path_y: &[i32],
    num: i32,
) -> Result<Vec<Cell>, LocalPathError> {
    for (array, len) in [
        ("GridPathX", grid_path_x.len()),
        ("GridPathY", grid_path_y.len()),
    ] {
        if num < 0 || len != num as usize {
            return Err(LocalPathError::PathLength { array, len, num });
        }
    }
    if num == 0 {
        return Err(LocalPathError::EmptyPath);
    }
    let mut cells = Vec::with_capacity(grid_path_x.len());
    let mut previous: Option<(i64, i64)> = None;
    for (index, (&x, &y)) in grid_path_x.iter().zip(grid_path_y).enumerate() {
        let (x, y) = (i64::from(x), i64::from(y));
        if !map.contains(x, y) {
            return Err(LocalPathError::PathCellOutside {
                index,
                x,
                y,
                width: map.width(),
                height: map.height(),
            });
        }
        if let Some((px, py)) = previous {
            let (dx, dy) = ((x - px).abs(), (y - py).abs());
            if dx > 1 || dy > 1 || (dx == 0 && dy == 0) {
                return Err(LocalPathError::PathNotAdjacent {
                    index,
                    from: (px, py),
                    to: (x, y),
                });
            }
        }
        previous = Some((x, y));
        cells.push((x as usize, y as usize));
    }
    Ok(cells)
}
