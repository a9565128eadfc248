//! Optimal paths on the 8-connected grid for GlobalPathPlanning (spec §5): octile costs, no
//! corner cutting, deterministic. A* over *jump points* (Harabor & Grastien, "Online Graph
//! Pruning for Pathfinding on Grid Maps", AAAI 2011; the rules for grids without corner
//! cutting as in "Improving Jump Point Search", ICAPS 2014).
//!
//! - **Moves**: the eight neighbours; a straight step costs 1, a diagonal √2, and a diagonal
//!   is allowed only when both orthogonal cells it passes are passable (no corner cutting,
//!   as the MovingAI benchmark counts).
//! - **Costs** are exact ([`OctileCost`]): step counts, compared through integer keys that
//!   order them exactly as the real numbers `a + b·√2`, so no rounding ever decides.
//! - **Jump points**: from an expanded cell, each direction the pruning rules keep is
//!   followed in a straight line until a cell where an optimal path may have to turn (a
//!   *forced* neighbour: a side cell that opens up where the cell behind it was blocked),
//!   the goal, or a wall; a diagonal stops where one of its two straight components would.
//!   Only those cells enter the open list. Every optimal path has a counterpart through
//!   jump points of equal length, so the result stays optimal (checked against every
//!   MovingAI problem and against Dijkstra on random maps); the cells between jump points
//!   are straight runs and are filled in when the path is read back.
//! - **Pruning**: a jump point is expanded only in the directions an optimal path may need
//!   from it: after a diagonal move, that diagonal and its two straight components; after a
//!   straight move, straight ahead, and a side (with the diagonal between ahead and that
//!   side) only where it is *forced* — the cell behind the side, beside the cell the move
//!   came from, is blocked. Where that cell is passable, the side cell and the diagonal
//!   ahead of it are reached at least as cheaply without the jump point.
//! - **Heuristic**: the octile distance, admissible and consistent (also along jumps), so a
//!   cell is expanded at most once and the goal's cost is optimal when it is taken.
//! - **Ties** (spec §6): equal `f = g + h` leave the queue in an order fixed by the order
//!   they entered it (the radix heap's), directions are tried in a fixed order, and a
//!   cell's parent changes only on a strictly lower cost: the same map, start and goal give
//!   the same path everywhere. Among equally short paths, the jump-point search prefers
//!   straight runs; [`AStar::plan_cellwise`] (plain A*, every cell a node) is kept for
//!   comparison and may pick another path of the same length.
//! - **Speed**: one byte per cell (passable, search generation, expanded, arrival move),
//!   with a blocked border so no step needs a bounds test, and a transposed copy of the
//!   passable flags so vertical runs read memory in order; marks are outdated by the next
//!   generation instead of cleared; `g` is recovered from the queue's `f`; the open list is
//!   a radix heap ([`super::heap`]). After a `MapUpdate` the planner is brought up to date
//!   where the map's distances changed ([`AStar::sync`]) instead of being rebuilt.

use super::cost::OctileCost;
use super::heap::{RadixHeap, RadixKey};
use crate::errors::GlobalPlanningError;
use crate::interfaces::GlobalPathCourse;
use crate::map::{Cell, GridMap, MapStamp, ORTHOGONAL_FIRST};

mod jump;
use jump::BitLines;

/// The eight moves `(dx, dy)` of [`ORTHOGONAL_FIRST`] (east, north, west, south, then the
/// diagonals NE, NW, SW, SE; diagonal `4 + k` lies between orthogonals `k` and `(k + 1) % 4`),
/// as bytes: a move's index is what a cell byte keeps.
const MOVES: [(i8, i8); 8] = {
    let mut moves = [(0, 0); 8];
    let mut k = 0;
    while k < 8 {
        moves[k] = (ORTHOGONAL_FIRST[k].0 as i8, ORTHOGONAL_FIRST[k].1 as i8);
        k += 1;
    }
    moves
};

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

/// Best costs, parents (jump points) and the open list, for one key width.
#[derive(Debug, Clone)]
struct Scratch<K> {
    g: Vec<K>,
    parent: Vec<u32>,
    open: RadixHeap<K>,
}

impl<K: RadixKey> Default for Scratch<K> {
    fn default() -> Self {
        Self {
            g: Vec::new(),
            parent: Vec::new(),
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
    /// The passable cells as bits, row by row and column by column (padded, border
    /// blocked), for the straight runs of the jumps: 64 cells a word.
    bits: BitLines,
    /// The map state `cells` was made from.
    stamp: MapStamp,
    generation: u8,
    small: Scratch<u64>,
    large: Scratch<u128>,
    /// The map's `GridSize` and origin, to say cells as positions in metres.
    geometry: (f64, (f64, f64)),
}

impl AStar {
    /// The planner for `map` with `dmin` metres (finite, ≥ 0).
    pub fn new(map: &GridMap, dmin: f64) -> Result<Self, GlobalPlanningError> {
        if !(dmin.is_finite() && dmin >= 0.0) {
            return Err(GlobalPlanningError::BadDmin { value: dmin });
        }
        let (w, h) = (map.width(), map.height());
        let mut planner = Self {
            width: w,
            height: h,
            dmin,
            passable_count: 0,
            cells: vec![0u8; (w + 2) * (h + 2)],
            bits: BitLines::new(w + 2, h + 2),
            stamp: map.stamp(),
            generation: 0,
            small: Scratch::default(),
            large: Scratch::default(),
            geometry: (map.grid_size(), map.origin()),
        };
        planner.mark(map, 0, 0, w, h);
        Ok(planner)
    }

    /// Brings the planner up to date with `map` (the same map after `MapUpdate`s, or
    /// another of the same size), keeping its scratch space: only the cells whose obstacle
    /// distance changed since are marked again (the map's change log), or all of them if
    /// that cannot be told. A map of another size gives a new planner.
    pub fn sync(&mut self, map: &GridMap) {
        self.geometry = (map.grid_size(), map.origin());
        if map.width() != self.width || map.height() != self.height {
            if let Ok(fresh) = Self::new(map, self.dmin) {
                *self = fresh;
            }
            return;
        }
        let stamp = map.stamp();
        if stamp == self.stamp {
            return;
        }
        match map.distance_changes_since(self.stamp) {
            Some(rects) => {
                for r in rects {
                    self.mark(map, r.x0, r.y0, r.x1, r.y1);
                }
            }
            None => self.mark(map, 0, 0, self.width, self.height),
        }
        self.stamp = stamp;
    }

    /// Marks the cells `[x0, x1) × [y0, y1)` passable or not from the map's distances
    /// (clearing their search marks), in both layouts, and keeps the count.
    fn mark(&mut self, map: &GridMap, x0: usize, y0: usize, x1: usize, y1: usize) {
        let w = self.width;
        let stride = w + 2;
        let dist = map.distances();
        for y in y0..y1 {
            for x in x0..x1 {
                let pass = !crate::map::within_dmin(dist[x + y * w], self.dmin);
                let p = (x + 1) + (y + 1) * stride;
                let before = self.cells[p] & PASSABLE != 0;
                self.cells[p] = if pass { PASSABLE } else { 0 };
                self.bits.set(x + 1, y + 1, pass);
                match (before, pass) {
                    (false, true) => self.passable_count += 1,
                    (true, false) => self.passable_count -= 1,
                    _ => {}
                }
            }
        }
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

    /// The optimal path from `start` to `goal`, by jump points.
    ///
    /// Errors: a cell outside the map, a blocked start or goal, or no path.
    pub fn plan(&mut self, start: Cell, goal: Cell) -> Result<GridPlan, GlobalPlanningError> {
        let wide = self.wide();
        self.plan_with(start, goal, wide, true)
    }

    /// The optimal path from `start` to `goal` by plain A*: every cell a node (the search
    /// as first written, kept to compare with). The same length as [`AStar::plan`]; where
    /// several paths are equally short it may pick another.
    pub fn plan_cellwise(
        &mut self,
        start: Cell,
        goal: Cell,
    ) -> Result<GridPlan, GlobalPlanningError> {
        let wide = self.wide();
        self.plan_with(start, goal, wide, false)
    }

    /// The centre of `cell` in metres (map frame).
    fn centre(&self, (x, y): Cell) -> (f64, f64) {
        let (g, (ox, oy)) = self.geometry;
        (ox + (x as f64 + 0.5) * g, oy + (y as f64 + 0.5) * g)
    }

    /// Whether costs need the `u128` key: every cost met has at most (passable cells − 1)
    /// steps of g plus max(width, height) steps of h.
    fn wide(&self) -> bool {
        let bound = self.passable_count + self.width.max(self.height);
        bound > OctileCost::SMALL_KEY_MAX as usize
    }

    /// [`AStar::plan`] (`jump`) or [`AStar::plan_cellwise`] with the `u64` or (`wide`) the
    /// `u128` cost key.
    fn plan_with(
        &mut self,
        start: Cell,
        goal: Cell,
        wide: bool,
        jump: bool,
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
                    at: self.centre(cell),
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
        let mut search = Search {
            cells: &mut self.cells,
            bits: &self.bits,
            stride: self.width + 2,
            generation: self.generation,
            goal,
        };
        let found = match (wide, jump) {
            (false, true) => search.jump(s, t, start, &mut self.small),
            (true, true) => search.jump(s, t, start, &mut self.large),
            (false, false) => search.run(s, t, start, &mut self.small),
            (true, false) => search.run(s, t, start, &mut self.large),
        };
        let Some(expanded) = found else {
            return Err(GlobalPlanningError::NoPath {
                start,
                goal,
                start_at: self.centre(start),
                goal_at: self.centre(goal),
            });
        };
        let parents = match (jump, wide) {
            (false, _) => None,
            (true, false) => Some(&self.small.parent[..]),
            (true, true) => Some(&self.large.parent[..]),
        };
        Ok(self.path(s, t, expanded, parents))
    }

    /// Reads the path back from the goal: along each cell's arrival move, one step at a
    /// time, to its parent (`parents`: the jump point it was reached from; `None`: the
    /// neighbour behind it), and counts the steps.
    fn path(&self, s: usize, t: usize, expanded: usize, parents: Option<&[u32]>) -> GridPlan {
        let stride = self.stride() as isize;
        let mut cells = vec![self.cell_of(t)];
        let mut cost = OctileCost::ZERO;
        let mut p = t;
        while p != s {
            let k = usize::from(self.cells[p] & MOVE_MASK);
            let (dx, dy) = MOVES[k];
            let back = -(isize::from(dx) + isize::from(dy) * stride);
            let step = if k < 4 {
                OctileCost::STRAIGHT
            } else {
                OctileCost::DIAGONAL
            };
            let parent = parents.map_or(p.wrapping_add_signed(back), |ps| ps[p] as usize);
            while p != parent {
                p = p.wrapping_add_signed(back);
                cells.push(self.cell_of(p));
                cost = cost + step;
            }
        }
        cells.reverse();
        GridPlan {
            cells,
            cost,
            expanded,
        }
    }
}

/// What both searches (cell by cell and over jump points) work with: the tag of this
/// generation's reached cells, the moves as index offsets, the step costs as keys and the
/// heuristic.
struct Costs<K> {
    tag: u8,
    offsets: [isize; 8],
    straight: K,
    diagonal: K,
    heuristic: Octile<K>,
}

/// The octile distance to the goal as a key: (max − min) + min·√2 = max·1 + min·(√2 − 1),
/// so max·key(1) + min·(key(√2) − key(1)) (keys are linear and exact).
#[derive(Clone, Copy)]
struct Octile<K> {
    unit: K,
    /// key(√2) − key(1).
    extra: K,
    goal: (u32, u32),
}

impl<K: Key> Octile<K> {
    #[inline(always)]
    fn at(self, x: u32, y: u32) -> K {
        let (dx, dy) = (x.abs_diff(self.goal.0), y.abs_diff(self.goal.1));
        K::times(self.unit, dx.max(dy)) + K::times(self.extra, dx.min(dy))
    }
}

/// One search over the cell bytes.
struct Search<'a> {
    cells: &'a mut [u8],
    bits: &'a BitLines,
    stride: usize,
    generation: u8,
    goal: Cell,
}

impl Search<'_> {
    /// Starts a search from padded index `s` (cell `start`): `scratch.g` covers the cells,
    /// `s` is reached at cost 0 and is alone in the open list. Returns the search's costs.
    #[inline(always)]
    fn begin<K: Key>(
        &mut self,
        s: usize,
        start: Cell,
        scratch: &mut Scratch<K>,
    ) -> Option<Costs<K>> {
        let n = self.cells.len();
        if scratch.g.len() < n {
            scratch.g.resize(n, K::default());
        }
        let stride = self.stride as isize;
        let (straight, diagonal) = (K::of(OctileCost::STRAIGHT), K::of(OctileCost::DIAGONAL));
        let costs = Costs {
            tag: PASSABLE | (self.generation << GENERATION_SHIFT),
            offsets: MOVES.map(|(dx, dy)| isize::from(dx) + isize::from(dy) * stride),
            straight,
            diagonal,
            heuristic: Octile {
                unit: straight,
                extra: diagonal - straight,
                goal: (self.goal.0 as u32, self.goal.1 as u32),
            },
        };
        self.cells[s] = costs.tag;
        scratch.g[s] = K::default();
        scratch.open.clear();
        let h = costs.heuristic.at(start.0 as u32, start.1 as u32);
        scratch.open.push(h, s as u32).ok()?;
        Some(costs)
    }

    /// Runs A* from padded index `s` to `t`; returns the number of expanded cells if the
    /// goal was reached (its parent moves are then in the cell bytes).
    fn run<K: Key>(
        &mut self,
        s: usize,
        t: usize,
        start: Cell,
        scratch: &mut Scratch<K>,
    ) -> Option<usize> {
        let Costs {
            tag,
            offsets,
            straight,
            diagonal,
            heuristic,
        } = self.begin(s, start, scratch)?;
        let stride = self.stride;
        let cells = &mut *self.cells;
        let g = &mut scratch.g[..cells.len()];
        let open = &mut scratch.open;
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
            let gp = f - heuristic.at(px - 1, py - 1);
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
                open.push(ng + heuristic.at(mx, my), m as u32).ok()?;
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
            let narrow = astar.plan_with(s, t, false, true);
            let wide = astar.plan_with(s, t, true, true);
            assert_eq!(narrow, wide, "{s:?} → {t:?}");
            let (narrow_cells, wide_cells) = (
                astar.plan_with(s, t, false, false),
                astar.plan_with(s, t, true, false),
            );
            assert_eq!(narrow_cells, wide_cells, "{s:?} → {t:?}");
            // Jump points or every cell: the same length.
            assert_eq!(
                narrow.as_ref().map(|p| p.cost),
                narrow_cells.as_ref().map(|p| p.cost)
            );
            solved += usize::from(narrow.is_ok());
        }
        assert!(solved > 50, "{solved}");
        // More searches than generations: the marks were cleared and reused correctly.
        assert_eq!(
            astar.plan_with((0, 0), (0, 0), false, true).is_ok(),
            map.cells()[0] == 0
        );
    }
}
