//! A* on the 8-connected grid (spec §5 "GlobalPathPlanning"): octile costs, no corner
//! cutting, optimal, deterministic.
//!
//! - **Moves**: the eight neighbours; a straight step costs 1, a diagonal √2, and a diagonal
//!   is allowed only when both orthogonal cells it passes are passable (no corner cutting,
//!   as the MovingAI benchmark counts).
//! - **Costs** are exact ([`OctileCost`]): step counts, compared through integer keys that
//!   order them exactly as the real numbers `a + b·√2`, so no rounding ever decides.
//! - **Heuristic**: the octile distance, admissible and consistent, so a cell is expanded at
//!   most once and the goal's cost is optimal when it is taken from the queue.
//! - **Ties** (spec §6): cells with equal `f = g + h` leave the queue in an order fixed by
//!   the order they entered it (the last one in first, as far as the radix heap's buckets
//!   allow); neighbours are visited in a fixed order and a cell's parent changes only on a
//!   strictly lower cost. The same map, start and goal give the same path everywhere.
//! - **Speed**: one byte per cell holds everything the inner loop reads about a neighbour
//!   (passable, search generation, expanded, parent move), with a blocked border so no
//!   neighbour needs a bounds test; the marks of a search are not cleared but outdated by
//!   the next generation (cleared only every 7 searches); `g` is recovered from the queue's
//!   `f` when a cell is expanded; and the open list is a radix heap ([`super::heap`]), which
//!   suits A*'s never-decreasing `f`: adding is O(1) and taking the minimum cheap.

use super::cost::OctileCost;
use super::heap::{RadixHeap, RadixKey};
use crate::errors::GlobalPlanningError;
use crate::interfaces::GlobalPathCourse;
use crate::map::{Cell, GridMap};

/// The eight moves `(dx, dy)`: east, north, west, south, then the diagonals NE, NW, SW, SE.
/// Diagonal `4 + k` lies between orthogonals `k` and `(k + 1) % 4`.
const MOVES: [(i8, i8); 8] = [
    (1, 0),
    (0, 1),
    (-1, 0),
    (0, -1),
    (1, 1),
    (-1, 1),
    (-1, -1),
    (1, -1),
];

/// A plan: the cells from start to goal and their cost.
#[derive(Debug, Clone, PartialEq)]
pub struct GridPlan {
    /// Cells from the start to the goal, both included; consecutive cells are 8-adjacent.
    pub cells: Vec<Cell>,
    /// The path's cost (straight and diagonal steps).
    pub cost: OctileCost,
    /// How many cells the search expanded (for comparisons and benchmarks).
    pub expanded: usize,
}

impl GridPlan {
    /// Path length in cells: straight steps + √2 · diagonal steps.
    pub fn length_cells(&self) -> f64 {
        self.cost.cells()
    }

    /// Path length in metres on a map of `grid_size`.
    pub fn length(&self, grid_size: f64) -> f64 {
        self.cost.cells() * grid_size
    }

    /// As the `GlobalPathCourse` LocalPathPlanning takes (000 §3.2.2.1 (6)).
    pub fn to_course(&self) -> GlobalPathCourse {
        GlobalPathCourse::from_cells(&self.cells)
    }
}

/// A cost key ordered exactly as the cost: [`OctileCost::small_key`] or [`OctileCost::key`].
trait Key:
    Copy
    + Ord
    + Default
    + core::ops::Add<Output = Self>
    + core::ops::Sub<Output = Self>
    + core::fmt::Debug
    + RadixKey
{
    fn of(cost: OctileCost) -> Self;
    /// `n` times `self`.
    fn times(self, n: u32) -> Self;
}

impl Key for u64 {
    fn of(cost: OctileCost) -> Self {
        cost.small_key()
    }
    fn times(self, n: u32) -> Self {
        self * u64::from(n)
    }
}

impl Key for u128 {
    fn of(cost: OctileCost) -> Self {
        cost.key()
    }
    fn times(self, n: u32) -> Self {
        self * u128::from(n)
    }
}

/// Best costs and the open list, for one key width.
#[derive(Debug, Clone)]
struct Scratch<K> {
    g: Vec<K>,
    open: RadixHeap<K>,
}

impl<K: RadixKey> Default for Scratch<K> {
    fn default() -> Self {
        Self {
            g: Vec::new(),
            open: RadixHeap::default(),
        }
    }
}

/// Bits of a cell's byte: passable (bit 7, read as `byte >> 7` in the search), the search
/// generation (1..=7; 0 = never reached), the cell was expanded, and the move that reached it.
const PASSABLE: u8 = 0b1000_0000;
const GENERATION_SHIFT: u32 = 4;
const GENERATION_MASK: u8 = 0b0111_0000;
const CLOSED: u8 = 0b0000_1000;
const MOVE_MASK: u8 = 0b0000_0111;
/// Generations 1..=7 fit the three bits; then the marks are cleared once.
const LAST_GENERATION: u8 = 7;

/// The A* planner for one map and one `dmin` (spec §5 "GlobalPathPlanning").
///
/// A cell is passable when its obstacle distance exceeds `dmin` (with `dmin = 0`, exactly
/// the free cells; spec §2, 000 §5.2.4.9 "dmin 以下の格子は通行不可"); outside the map is
/// blocked. The planner copies what it needs from the map when it is made: a later change
/// to the map (or to `dmin`) needs a new planner. It keeps its scratch space between plans,
/// so repeated plans allocate only the returned path.
///
/// Costs use the `u64` key when no cost on the grid can leave its exact range (about a
/// million passable cells), otherwise the `u128` key; both order costs exactly, so both
/// give the same path.
#[derive(Debug, Clone)]
pub struct AStar {
    width: usize,
    height: usize,
    dmin: f64,
    passable_count: usize,
    /// `(width + 2) × (height + 2)` cell bytes, x fastest, border blocked.
    cells: Vec<u8>,
    generation: u8,
    small: Scratch<u64>,
    large: Scratch<u128>,
}

impl AStar {
    /// The planner for `map` with `dmin` metres (finite, ≥ 0).
    pub fn new(map: &GridMap, dmin: f64) -> Result<Self, GlobalPlanningError> {
        if !(dmin.is_finite() && dmin >= 0.0) {
            return Err(GlobalPlanningError::BadDmin { value: dmin });
        }
        let (w, h) = (map.width(), map.height());
        let stride = w + 2;
        let mut cells = vec![0u8; stride * (h + 2)];
        let mut passable_count = 0;
        for (y, row) in map.distances().chunks_exact(w).enumerate() {
            let dst = &mut cells[(y + 1) * stride + 1..(y + 1) * stride + 1 + w];
            for (c, &d) in dst.iter_mut().zip(row) {
                if !crate::map::within_dmin(d, dmin) {
                    *c = PASSABLE;
                    passable_count += 1;
                }
            }
        }
        Ok(Self {
            width: w,
            height: h,
            dmin,
            passable_count,
            cells,
            generation: 0,
            small: Scratch::default(),
            large: Scratch::default(),
        })
    }

    /// Cells in x.
    pub fn width(&self) -> usize {
        self.width
    }

    /// Cells in y.
    pub fn height(&self) -> usize {
        self.height
    }

    /// The `dmin` it was made for (m).
    pub fn dmin(&self) -> f64 {
        self.dmin
    }

    /// How many cells are passable.
    pub fn passable_count(&self) -> usize {
        self.passable_count
    }

    fn stride(&self) -> usize {
        self.width + 2
    }

    /// Padded index of an in-map cell.
    fn padded_index(&self, (x, y): Cell) -> usize {
        (x + 1) + (y + 1) * self.stride()
    }

    /// The cell of a padded index.
    fn cell_of(&self, p: usize) -> Cell {
        let s = self.stride();
        (p % s - 1, p / s - 1)
    }

    /// Whether `(x, y)` (possibly outside the map) may be entered.
    pub fn is_passable(&self, x: i64, y: i64) -> bool {
        x >= 0
            && y >= 0
            && (x as u64) < self.width as u64
            && (y as u64) < self.height as u64
            && self.cells[self.padded_index((x as usize, y as usize))] & PASSABLE != 0
    }

    /// Whether one step from `a` to `b` is legal: both passable, 8-adjacent (and distinct),
    /// and a diagonal only when both orthogonal cells it passes are passable (no corner
    /// cutting).
    pub fn step_allowed(&self, a: Cell, b: Cell) -> bool {
        let (ax, ay, bx, by) = (a.0 as i64, a.1 as i64, b.0 as i64, b.1 as i64);
        let (dx, dy) = (bx - ax, by - ay);
        if dx.abs() > 1 || dy.abs() > 1 || (dx == 0 && dy == 0) {
            return false;
        }
        self.is_passable(ax, ay)
            && self.is_passable(bx, by)
            && (dx == 0 || dy == 0 || (self.is_passable(bx, ay) && self.is_passable(ax, by)))
    }

    /// The optimal path from `start` to `goal`.
    ///
    /// Errors: a cell outside the map, a blocked start or goal, or no path.
    pub fn plan(&mut self, start: Cell, goal: Cell) -> Result<GridPlan, GlobalPlanningError> {
        // Every cost met has at most (passable cells − 1) steps of g plus max(width, height)
        // steps of h.
        let bound = self.passable_count + self.width.max(self.height);
        self.plan_with(start, goal, bound > OctileCost::SMALL_KEY_MAX as usize)
    }

    /// [`AStar::plan`] with the `u64` or (`wide`) the `u128` cost key.
    fn plan_with(
        &mut self,
        start: Cell,
        goal: Cell,
        wide: bool,
    ) -> Result<GridPlan, GlobalPlanningError> {
        for (which, cell) in [("start", start), ("goal", goal)] {
            if cell.0 >= self.width || cell.1 >= self.height {
                return Err(GlobalPlanningError::CellOutside {
                    which,
                    cell,
                    width: self.width,
                    height: self.height,
                });
            }
            if self.cells[self.padded_index(cell)] & PASSABLE == 0 {
                return Err(GlobalPlanningError::Blocked {
                    which,
                    cell,
                    dmin: self.dmin,
                });
            }
        }
        if self.generation >= LAST_GENERATION {
            for c in &mut self.cells {
                *c &= PASSABLE;
            }
            self.generation = 0;
        }
        self.generation += 1;
        let s = self.padded_index(start);
        let t = self.padded_index(goal);
        let stride = self.stride();
        let mut search = Search {
            cells: &mut self.cells,
            stride,
            generation: self.generation,
            goal,
        };
        let found = if wide {
            search.run(s, t, start, &mut self.large)
        } else {
            search.run(s, t, start, &mut self.small)
        };
        let Some(expanded) = found else {
            return Err(GlobalPlanningError::NoPath { start, goal });
        };
        Ok(self.path(s, t, expanded))
    }

    /// Follows the parent moves back from the goal and counts the steps.
    fn path(&self, s: usize, t: usize, expanded: usize) -> GridPlan {
        let stride = self.stride() as isize;
        let mut cells = vec![self.cell_of(t)];
        let mut cost = OctileCost::ZERO;
        let mut p = t;
        while p != s {
            let k = usize::from(self.cells[p] & MOVE_MASK);
            let (dx, dy) = MOVES[k];
            p = p.wrapping_add_signed(-(isize::from(dx) + isize::from(dy) * stride));
            cells.push(self.cell_of(p));
            cost = cost
                + if k < 4 {
                    OctileCost::STRAIGHT
                } else {
                    OctileCost::DIAGONAL
                };
        }
        cells.reverse();
        GridPlan {
            cells,
            cost,
            expanded,
        }
    }
}

/// One search over the cell bytes.
struct Search<'a> {
    cells: &'a mut [u8],
    stride: usize,
    generation: u8,
    goal: Cell,
}

impl Search<'_> {
    /// Runs A* from padded index `s` to `t`; returns the number of expanded cells if the
    /// goal was reached (its parent moves are then in the cell bytes).
    fn run<K: Key>(
        &mut self,
        s: usize,
        t: usize,
        start: Cell,
        scratch: &mut Scratch<K>,
    ) -> Option<usize> {
        let cells = &mut *self.cells;
        if scratch.g.len() < cells.len() {
            scratch.g.resize(cells.len(), K::default());
        }
        let g = &mut scratch.g[..cells.len()];
        let open = &mut scratch.open;
        open.clear();
        let generation = self.generation;
        let tag = PASSABLE | (generation << GENERATION_SHIFT);
        let stride = self.stride;
        let offsets: [isize; 8] =
            MOVES.map(|(dx, dy)| isize::from(dx) + isize::from(dy) * stride as isize);
        let straight = K::of(OctileCost::STRAIGHT);
        let diagonal = K::of(OctileCost::DIAGONAL);
        let (gx, gy) = (self.goal.0 as u32, self.goal.1 as u32);
        // h of a cell: (max − min) + min·√2 = max·1 + min·(√2 − 1): as a key, max·key(1) +
        // min·(key(√2) − key(1)) (keys are linear and exact).
        let (unit, extra) = (straight, diagonal - straight);
        let heuristic = |x: u32, y: u32| {
            let (dx, dy) = (x.abs_diff(gx), y.abs_diff(gy));
            K::times(unit, dx.max(dy)) + K::times(extra, dx.min(dy))
        };
        cells[s] = tag;
        g[s] = K::default();
        let h = heuristic(start.0 as u32, start.1 as u32);
        open.push(h, s as u32).ok()?;
        let mut expanded = 0usize;
        while let Some((f, node)) = open.pop() {
            let p = node as usize;
            if cells[p] & CLOSED != 0 {
                continue;
            }
            cells[p] |= CLOSED;
            expanded += 1;
            if p == t {
                return Some(expanded);
            }
            // Padded coordinates: (x + 1, y + 1); 32-bit division (a map has < 2^24 cells).
            let (px, py) = (p as u32 % stride as u32, p as u32 / stride as u32);
            // g from the queue's f (keys are exact and linear): no read of g[p].
            let gp = f - heuristic(px - 1, py - 1);
            // Bit k set: orthogonal move k leads to a passable cell.
            let orth = (cells[p + 1] >> 7)
                | (cells[p + stride] >> 7) << 1
                | (cells[p - 1] >> 7) << 2
                | (cells[p - stride] >> 7) << 3;
            // Diagonal 4 + j needs orthogonals j and (j + 1) % 4 (no corner cutting).
            let diagonals = orth & ((orth >> 1) | ((orth & 1) << 3));
            let mut moves = orth | (diagonals << 4);
            while moves != 0 {
                let k = moves.trailing_zeros() as usize;
                moves &= moves - 1;
                let m = p.wrapping_add_signed(offsets[k]);
                let c = cells[m];
                let step = if k < 4 {
                    straight
                } else {
                    if c & PASSABLE == 0 {
                        continue;
                    }
                    diagonal
                };
                let ng = gp + step;
                let reached = c & GENERATION_MASK == tag & GENERATION_MASK;
                if reached && (c & CLOSED != 0 || ng >= g[m]) {
                    continue;
                }
                cells[m] = tag | k as u8;
                g[m] = ng;
                let (dx, dy) = MOVES[k];
                let mx = (px as i32 + i32::from(dx)) as u32 - 1;
                let my = (py as i32 + i32::from(dy)) as u32 - 1;
                // Never fails: f never decreases (consistent heuristic, exact keys).
                open.push(ng + heuristic(mx, my), m as u32).ok()?;
            }
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Both key widths order costs exactly, so they give the same paths.
    #[test]
    fn both_key_widths_give_the_same_paths() {
        let mut seed = 99u64;
        let (w, h) = (37, 23);
        let cells: Vec<u8> = (0..w * h)
            .map(|_| {
                seed = seed
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                u8::from((seed >> 33) % 100 < 25)
            })
            .collect();
        let map = GridMap::new(w, h, 1.0, (0.0, 0.0), cells).unwrap();
        let mut astar = AStar::new(&map, 0.0).unwrap();
        let mut solved = 0;
        for i in 0..200 {
            let s = ((i * 7) % w, (i * 13) % h);
            let t = ((i * 29 + 5) % w, (i * 3 + 11) % h);
            let narrow = astar.plan_with(s, t, false);
            let wide = astar.plan_with(s, t, true);
            assert_eq!(narrow, wide, "{s:?} → {t:?}");
            solved += usize::from(narrow.is_ok());
        }
        assert!(solved > 50, "{solved}");
        // More searches than generations: the marks were cleared and reused correctly.
        assert_eq!(
            astar.plan_with((0, 0), (0, 0), false).is_ok(),
            map.cells()[0] == 0
        );
    }
}
