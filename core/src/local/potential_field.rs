//! The potential field of 000 §5.2.4.9 (spec §3 step 4), as a value other code can read and
//! draw: per cell the potential `G`, its three parts (repulsion `R`, attraction `A`, posture
//! `P`), the path length `L` to the local target, and a state.
//!
//! **Order (spec §3 step 4 Decision)**: the field grows from the local target in Dijkstra
//! order. A cell is *assigned* once, when its first 8-neighbour is *finalized* (popped from
//! the queue): `G(c) = G(p) + R(c) + A(c) + P(c)`, `L(c) = L(p) + step(p, c)`. Every increment
//! is positive, so cells are finalized in increasing `(G, assignment order)`, and the parent
//! `p` — the first finalized neighbour — is the neighbour with the lowest potential, as the
//! seed requires ("Gn は隣接するグリッドの中で一番低いポテンシャル値").
//!
//! **Region computed**: with [`FieldExtent::Full`] every cell connected to the target (in the
//! `dmin`-inflated grid) is reached. With [`FieldExtent::UntilCurrent`] (the default) the
//! field stops as soon as the current cell is finalized, as the original stops when it has
//! what it needs: then exactly the cells whose key `(G, order)` is below the current cell's
//! are finalized, plus the frontier of cells already assigned. A cell's values are fixed when
//! it is assigned, so every reached cell of a stopped field has the same values as in the
//! full field, and the descent of [`crate::local::descend`] — which only ever steps to
//! finalized cells below the current one — yields the same path (tested in
//! `tests/local_path_planning_field.rs`). The heat map then shows the region "below the
//! robot"; the GUI may ask for the full field.
//!
//! **Speed** (the values are those of [`super::reference`], bit for bit; property-tested in
//! `tests/field_reference.rs`):
//! - nothing per plan is proportional to the map: the buffers are kept, the cells the last
//!   plan reached are reset, and the impassable marks (obstacle distance ≤ `dmin`) are kept
//!   too — redone only where the map's distances changed since (the map's stamp and change
//!   log, `GridMap::distance_changes_since`), or everywhere for a new map or `dmin`;
//! - what the expansion of a neighbour reads is one 32-bit word per cell: state, parent and
//!   the squared obstacle distance in cells², whose repulsion comes from a table (the same
//!   `1 / (d − dmin)²` of the same metres); a cell's record is `G` and `L`, 16 bytes; the
//!   attraction and posture parts are computed again when asked for
//!   ([`PotentialField::info`]) by the same formulas on the same numbers; finalization ranks
//!   are kept as the order list and indexed on demand;
//! - a bucket queue (`field_queue.rs`) that carries `L` with `G`, so a finalized cell is
//!   expanded without reading its record back;
//! - both posture angles by [`super::angle`]'s `atan2`, `libm::atan2` bit for bit without
//!   its data-dependent branches.

use std::cell::OnceCell;

use serde::{Deserialize, Serialize};

use super::angle::atan2_nonneg;
use super::field_queue::{Entry, FieldQueue};
use super::field_word::{
    D2_SHIFT, IMPASSABLE, PARENT_MASK, PARENT_SHIFT, RAW_D2, REACHED, Repulsion, STATE_MASK,
    UNREACHED,
};
use crate::errors::LocalPathError;
use crate::interfaces::Direction;
use crate::map::{Cell, GridMap, MapStamp, NEIGHBOURS};

/// The potential of the local target (000 §5.2.4.9: "ポテンシャル値(0.1)を設定").
pub const TARGET_POTENTIAL: f64 = 0.1;

const NOT_FINAL: u32 = u32::MAX;
/// A reset sweeps the whole field instead of visiting the reached cells once more than one
/// cell in this many was reached (a sweep costs about what visiting a third of the cells
/// in the order they were reached does: a full field on 1000 × 1000 cells reset in 3.4 ms
/// instead of 12.4 ms).
const RESET_SWEEP: usize = 3;

/// What a cell of the field is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize)]
#[repr(u8)]
pub enum CellState {
    /// Passable but not reached (not connected to the target, or beyond where the field
    /// stopped, see [`FieldExtent`]). Potential 0.
    Unreached = 0,
    /// Has a potential, its parts and `L`.
    Reached = 1,
    /// Obstacle distance ≤ `dmin` (000 §5.2.4.9: "通行が出来ないグリッド"): potential 0,
    /// never entered.
    Impassable = 2,
}

impl CellState {
    /// From its code: 0 unreached, 1 reached, 2 impassable (anything else: unreached).
    pub fn from_code(code: u8) -> Self {
        match code {
            1 => Self::Reached,
            2 => Self::Impassable,
            _ => Self::Unreached,
        }
    }
}

/// How much of the field to compute (see the module documentation).
#[derive(
    Debug, Clone, Copy, Default, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, Deserialize,
)]
pub enum FieldExtent {
    /// Stop once the current cell is finalized: same path, less work.
    #[default]
    UntilCurrent,
    /// Every cell connected to the target.
    Full,
}

/// What a field is computed for.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct FieldRequest {
    /// The local target cell (potential 0.1, `L` = 0).
    pub target: Cell,
    /// The current cell: where the descent starts; the origin of `SL` and `S_Angle`.
    pub current: Cell,
    /// The robot's current heading \[rad\].
    pub current_heading: f64,
    /// The robot's heading wanted at the target \[rad\].
    pub target_heading: f64,
    /// Forward, or backward: then both headings are turned by π (spec §3 step 4), since
    /// the robot moves against its heading.
    pub direction: Direction,
    /// `dmin` \[m\]: cells with obstacle distance ≤ `dmin` are impassable.
    pub dmin: f64,
    /// `PostureConsiderationLevel` \[%\], 0–100.
    pub posture_consideration_level: f64,
    /// Whether the posture part is used; the planner turns it off within
    /// `NotPostureDistance` of the goal (000 §5.2.4.9).
    pub posture: bool,
    /// How much to compute.
    pub extent: FieldExtent,
}

/// Everything the field knows about one cell (the GUI's hover inspector).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CellInfo {
    /// The cell.
    pub cell: Cell,
    /// Its state.
    pub state: CellState,
    /// Potential `G` (0 unless reached).
    pub potential: f64,
    /// Repulsion `R = 1 / (d − dmin)²`.
    pub repulsion: f64,
    /// Attraction `A = L · (100 − PCL) / 100`.
    pub attraction: f64,
    /// Posture `P`.
    pub posture: f64,
    /// Path length `L` to the target along the parents \[m\].
    pub length: f64,
    /// The neighbour it got its potential from.
    pub parent: Option<Cell>,
    /// Its place in the finalization order (`None` if not finalized).
    pub rank: Option<u32>,
}

/// One cell of the field: the potential `G` and the path length `L` to the target.
/// Both are 0 on impassable and unreached cells. The parts of `G` follow from the cell,
/// `L` and the request ([`PotentialField::info`]).
///
/// 16 bytes, aligned to 16: four cells to a cache line, none straddling two.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize)]
#[repr(C, align(16))]
pub struct FieldCell {
    /// Potential `G`.
    pub potential: f64,
    /// Path length `L` to the target along the parents \[m\].
    pub length: f64,
}

impl FieldCell {
    const EMPTY: Self = Self {
        potential: 0.0,
        length: 0.0,
    };
}

/// The potential field "PotentialMap[][]" of 000 §5.2.4.9: the map's size, one
/// [`FieldCell`] and one [`CellState`] per cell (x fastest, as the map).
#[derive(Clone, Default)]
pub struct PotentialField {
    width: usize,
    height: usize,
    grid_size: f64,
    cells: Vec<FieldCell>,
    /// Per cell: state, parent and squared obstacle distance (see [`STATE_MASK`]).
    words: Vec<u32>,
    /// The repulsion of the grid size and `dmin` of `marks` by squared distance below
    /// [`TABLE_D2`](super::field_word::TABLE_D2), and of the cells marked [`RAW_D2`].
    repulsion: Repulsion,
    /// Cells assigned by the last computation, in assignment order (reset on the next).
    touched: Vec<u32>,
    /// Cells finalized by the last computation, in order: a cell's rank is its index.
    order: Vec<u32>,
    /// The ranks per cell, made from `order` when first asked for.
    ranks: OnceCell<Vec<u32>>,
    /// The Dijkstra queue: potential bits, ties in assignment order.
    queue: FieldQueue,
    request: Option<FieldRequest>,
    /// What the impassable marks and `d2` were made from: the map's stamp and `dmin`.
    marks: Option<(MapStamp, u64)>,
    /// The map's stamp while a computation is unfinished ([`PotentialField::resume`]).
    growing: Option<MapStamp>,
    complete: bool,
    current_reached: bool,
}

impl core::fmt::Debug for PotentialField {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("PotentialField")
            .field("width", &self.width)
            .field("height", &self.height)
            .field("grid_size", &self.grid_size)
            .field("request", &self.request)
            .field("reached", &self.touched.len())
            .field("finalized", &self.order.len())
            .field("complete", &self.complete)
            .field("current_reached", &self.current_reached)
            .finish_non_exhaustive()
    }
}

/// The constants of one computation, from its request and map.
#[derive(Debug, Clone, Copy)]
struct Terms {
    step_straight: f64,
    step_diagonal: f64,
    attraction_factor: f64,
    posture_factor: f64,
    posture_on: bool,
    /// Unit vectors of the motion headings at the current position and at the target.
    hs: (f64, f64),
    ht: (f64, f64),
    current: (i64, i64),
    target: (i64, i64),
}

impl Terms {
    fn new(grid_size: f64, req: &FieldRequest) -> Self {
        let turn = match req.direction {
            Direction::Forward => 0.0,
            Direction::Backward => core::f64::consts::PI,
        };
        let posture_factor = req.posture_consideration_level / 100.0;
        Self {
            step_straight: grid_size,
            step_diagonal: f64::sqrt(2.0) * grid_size,
            attraction_factor: (100.0 - req.posture_consideration_level) / 100.0,
            posture_factor,
            posture_on: req.posture && posture_factor > 0.0,
            hs: (
                libm::cos(req.current_heading + turn),
                libm::sin(req.current_heading + turn),
            ),
            ht: (
                libm::cos(req.target_heading + turn),
                libm::sin(req.target_heading + turn),
            ),
            current: (req.current.0 as i64, req.current.1 as i64),
            target: (req.target.0 as i64, req.target.1 as i64),
        }
    }

    /// `P(c)` of a cell at `(x, y)` with path length `l`.
    #[inline(always)]
    fn posture(&self, x: i64, y: i64, l: f64) -> f64 {
        if self.posture_on {
            self.posture_factor
                * posture_terms(
                    x - self.current.0,
                    y - self.current.1,
                    self.target.0 - x,
                    self.target.1 - y,
                    self.hs,
                    self.ht,
                    l,
                )
        } else {
            0.0
        }
    }
}

impl PotentialField {
    /// An empty field (0 × 0); [`PotentialField::compute`] sizes it to the map.
    pub fn new() -> Self {
        Self::default()
    }

    /// Computes the field for `request` on `map`, reusing this field's buffers.
    ///
    /// Errors: a request cell outside the map, a parameter out of range or not finite
    /// (then the field is left as it was); the target within `dmin` of an obstacle
    /// ([`LocalPathError::TargetBlocked`]) or the current cell never reached
    /// ([`LocalPathError::NoRoute`]) — then the field holds what was computed, for display.
    pub fn compute(&mut self, map: &GridMap, request: &FieldRequest) -> Result<(), LocalPathError> {
        self.compute_within(map, request, usize::MAX).map(drop)
    }

    /// [`PotentialField::compute`], finalizing at most `budget` cells now (spec §3 Decision
    /// 0.2, "A local plan over executions"): `Ok(true)` when the field is done — then the same
    /// field and result as `compute` —, `Ok(false)` when [`PotentialField::resume`] goes on
    /// from where this stopped. The cells are finalized in the same order either way.
    pub fn compute_within(
        &mut self,
        map: &GridMap,
        request: &FieldRequest,
        budget: usize,
    ) -> Result<bool, LocalPathError> {
        validate(map, request)?;
        self.reset(map, request);
        let target = map.index(request.target);
        if self.words[target] & STATE_MASK == IMPASSABLE {
            return Err(LocalPathError::TargetBlocked {
                from: request.target,
            });
        }
        self.cells[target].potential = TARGET_POTENTIAL;
        self.words[target] = (self.words[target] & !(STATE_MASK | PARENT_MASK)) | REACHED;
        self.touched.push(target as u32);
        self.queue
            .push(Entry::new(TARGET_POTENTIAL.to_bits(), 0.0, target as u32));
        self.growing = Some(map.stamp());
        self.resume(map, budget)
    }

    /// Goes on with an unfinished [`PotentialField::compute_within`] for at most `budget`
    /// more finalized cells: `Ok(true)` when done, with `compute`'s result. On a map that
    /// changed since it began, the computation begins again on this map. With nothing
    /// unfinished, the result of the last computation again.
    pub fn resume(&mut self, map: &GridMap, budget: usize) -> Result<bool, LocalPathError> {
        let Some(request) = self.request else {
            return Ok(true);
        };
        match self.growing {
            Some(stamp) if stamp != map.stamp() => {
                return self.compute_within(map, &request, budget);
            }
            Some(_) => {
                self.ranks = OnceCell::new();
                if !self.grow(map, &request, budget) {
                    return Ok(false);
                }
                self.growing = None;
            }
            None => {}
        }
        if self.current_reached {
            Ok(true)
        } else {
            Err(LocalPathError::NoRoute {
                target: request.target,
                current: request.current,
            })
        }
    }

    /// Clears what the last computation reached and brings the impassable marks and
    /// squared distances up to date with `map` and the request's `dmin`.
    fn reset(&mut self, map: &GridMap, request: &FieldRequest) {
        let n = map.width() * map.height();
        if self.width != map.width() || self.height != map.height() || self.cells.len() != n {
            self.width = map.width();
            self.height = map.height();
            self.cells = vec![FieldCell::EMPTY; n];
            self.words = vec![UNREACHED; n];
            self.marks = None;
        } else if self.touched.len() * RESET_SWEEP < n {
            // Reached cells were passable when marked; the marks are redone below where
            // the distances changed.
            for &i in &self.touched {
                self.cells[i as usize] = FieldCell::EMPTY;
                self.words[i as usize] &= !(STATE_MASK | PARENT_MASK);
            }
        } else {
            // Most of the map was reached: one sweep in memory order is cheaper than the
            // scattered writes, and leaves the same (only reached cells have a parent or a
            // value; impassable marks are kept).
            self.cells.fill(FieldCell::EMPTY);
            for w in &mut self.words {
                if *w & STATE_MASK == REACHED {
                    *w &= !(STATE_MASK | PARENT_MASK);
                }
            }
        }
        self.touched.clear();
        self.order.clear();
        self.ranks = OnceCell::new();
        self.queue.clear();
        let grid = map.grid_size();
        self.grid_size = grid;
        let dmin = request.dmin;
        let key = (map.stamp(), dmin.to_bits());
        let changes = match self.marks {
            Some((stamp, bits)) if bits == key.1 => map.distance_changes_since(stamp),
            _ => None,
        };
        let dist = map.distances();
        let w = self.width;
        match changes {
            Some(rects) => {
                for r in rects {
                    for y in r.y0..r.y1 {
                        let from = y * w + r.x0;
                        let row = from..y * w + r.x1;
                        self.repulsion
                            .mark(from, &dist[row.clone()], &mut self.words[row]);
                    }
                }
            }
            None => {
                self.repulsion = Repulsion::new(grid, dmin);
                self.repulsion.mark(0, dist, &mut self.words);
            }
        }
        self.marks = Some(key);
        self.request = Some(*request);
        self.growing = None;
        self.complete = false;
        self.current_reached = false;
    }

    /// Dijkstra growth from the target (000 §5.2.4.9, spec §3 step 4), at most `budget`
    /// cells finalized: whether it ended (the current cell finalized, for
    /// [`FieldExtent::UntilCurrent`], or the queue empty).
    fn grow(&mut self, map: &GridMap, req: &FieldRequest, budget: usize) -> bool {
        let (w, h) = (self.width, self.height);
        let dist = map.distances();
        let dmin = req.dmin;
        let t = Terms::new(map.grid_size(), req);
        let current = map.index(req.current);
        let until_current = req.extent == FieldExtent::UntilCurrent;
        let offsets: [isize; 8] = NEIGHBOURS.map(|(dx, dy)| dx as isize + dy as isize * w as isize);
        let steps = [t.step_straight, t.step_diagonal];
        let cells = &mut self.cells[..];
        let words = &mut self.words[..];
        let repulsion = &self.repulsion;
        let touched = &mut self.touched;
        let order = &mut self.order;
        let queue = &mut self.queue;

        let mut left = budget;
        while left > 0
            && let Some(entry) = queue.pop()
        {
            left -= 1;
            let (key, lp, cell) = (entry.key, entry.length, entry.cell);
            let i = cell as usize;
            order.push(cell);
            if i == current {
                self.current_reached = true;
                if until_current {
                    self.complete = queue.is_empty();
                    return true;
                }
            }
            let gp = f64::from_bits(key);
            let (px, py) = ((cell % w as u32) as usize, (cell / w as u32) as usize);
            let interior = px > 0 && py > 0 && px + 1 < w && py + 1 < h;
            for k in 0..8 {
                let (dx, dy) = NEIGHBOURS[k];
                if !interior {
                    let (nx, ny) = (px as i64 + dx, py as i64 + dy);
                    if nx < 0 || ny < 0 || nx >= w as i64 || ny >= h as i64 {
                        continue;
                    }
                }
                let ni = i.wrapping_add_signed(offsets[k]);
                let word = words[ni];
                if word & STATE_MASK != UNREACHED {
                    continue;
                }
                let diagonal = k & 1;
                if diagonal == 1
                    && (words[i.wrapping_add_signed(dx as isize)] & STATE_MASK == IMPASSABLE
                        || words[i.wrapping_add_signed(dy as isize * w as isize)] & STATE_MASK
                            == IMPASSABLE)
                {
                    // A diagonal step may not cut the corner of an impassable cell.
                    continue;
                }
                let l = lp + steps[diagonal];
                let r = match word >> D2_SHIFT {
                    RAW_D2 => {
                        let clearance = dist[ni] - dmin;
                        1.0 / (clearance * clearance)
                    }
                    k2 => repulsion.of(k2),
                };
                let a = l * t.attraction_factor;
                let p = t.posture(px as i64 + dx, py as i64 + dy, l);
                let gn = gp + r + a + p;
                cells[ni] = FieldCell {
                    potential: gn,
                    length: l,
                };
                words[ni] = word | REACHED | ((k as u32 + 1) << PARENT_SHIFT);
                touched.push(ni as u32);
                queue.push(Entry::new(gn.to_bits(), l, ni as u32));
            }
        }
        self.complete = queue.is_empty();
        self.complete
    }

    /// Cells in x.
    pub fn width(&self) -> usize {
        self.width
    }

    /// Cells in y.
    pub fn height(&self) -> usize {
        self.height
    }

    /// Cell size \[m\] of the map it was computed on.
    pub fn grid_size(&self) -> f64 {
        self.grid_size
    }

    /// The request of the last computation.
    pub fn request(&self) -> Option<&FieldRequest> {
        self.request.as_ref()
    }

    /// Every cell's potential and length, x fastest.
    pub fn cells(&self) -> &[FieldCell] {
        &self.cells
    }

    /// The potential of a cell (0 unless reached, and outside the field).
    pub fn potential(&self, cell: Cell) -> f64 {
        self.flat(cell).map_or(0.0, |i| self.cells[i].potential)
    }

    /// [`CellState`] of every cell, x fastest, as the map.
    pub fn states(&self) -> impl ExactSizeIterator<Item = CellState> + '_ {
        self.words
            .iter()
            .map(|&w| CellState::from_code((w & STATE_MASK) as u8))
    }

    fn flat(&self, (x, y): Cell) -> Option<usize> {
        (x < self.width && y < self.height).then_some(x + y * self.width)
    }

    /// The state of a cell (`Unreached` for a cell outside the field).
    pub fn state(&self, cell: Cell) -> CellState {
        self.flat(cell).map_or(CellState::Unreached, |i| {
            CellState::from_code((self.words[i] & STATE_MASK) as u8)
        })
    }

    /// The neighbour a reached cell got its potential from (`None` for the target and
    /// cells not reached).
    pub fn parent(&self, cell: Cell) -> Option<Cell> {
        let i = self.flat(cell)?;
        let k = (((self.words[i] & PARENT_MASK) >> PARENT_SHIFT) as usize).checked_sub(1)?;
        let (dx, dy) = NEIGHBOURS[k];
        Some(((cell.0 as i64 - dx) as usize, (cell.1 as i64 - dy) as usize))
    }

    /// The finalization rank of every cell ([`NOT_FINAL`] if not finalized), made once
    /// per computation from the order list.
    fn ranks(&self) -> &[u32] {
        self.ranks.get_or_init(|| {
            let mut ranks = vec![NOT_FINAL; self.cells.len()];
            for (rank, &c) in self.order.iter().enumerate() {
                ranks[c as usize] = rank as u32;
            }
            ranks
        })
    }

    /// A cell's place in the finalization order, if it was finalized.
    pub fn rank(&self, cell: Cell) -> Option<u32> {
        let i = self.flat(cell)?;
        let rank = self.ranks()[i];
        (rank != NOT_FINAL).then_some(rank)
    }

    /// The key the descent compares: `(G, finalization order)`; cells assigned but not
    /// finalized (the frontier of a stopped field) come after every finalized cell of equal
    /// potential. `None` unless reached.
    pub fn key(&self, cell: Cell) -> Option<(f64, u32)> {
        let i = self.flat(cell)?;
        (self.words[i] & STATE_MASK == REACHED).then(|| (self.cells[i].potential, self.ranks()[i]))
    }

    /// Everything about one cell, for the GUI's inspector; `None` outside the field. The
    /// three parts are computed again by the formulas that made the potential, from the
    /// same numbers (the cell's obstacle distance, its `L`, the request), so they are the
    /// very values that were added.
    pub fn info(&self, cell: Cell) -> Option<CellInfo> {
        let i = self.flat(cell)?;
        let c = &self.cells[i];
        let state = CellState::from_code((self.words[i] & STATE_MASK) as u8);
        let parent = self.parent(cell);
        let (repulsion, attraction, posture) = match &self.request {
            Some(req) if state == CellState::Reached && parent.is_some() => {
                let t = Terms::new(self.grid_size, req);
                let r = match self.words[i] >> D2_SHIFT {
                    RAW_D2 => self.repulsion.raw(i as u32).unwrap_or(0.0),
                    k2 => self.repulsion.of(k2),
                };
                (
                    r,
                    c.length * t.attraction_factor,
                    t.posture(cell.0 as i64, cell.1 as i64, c.length),
                )
            }
            _ => (0.0, 0.0, 0.0),
        };
        Some(CellInfo {
            cell,
            state,
            potential: c.potential,
            repulsion,
            attraction,
            posture,
            length: c.length,
            parent,
            rank: self.rank(cell),
        })
    }

    /// Whether every cell connected to the target was reached (the queue ran empty).
    pub fn is_complete(&self) -> bool {
        self.complete
    }

    /// Whether the current cell was reached (the plan can be made).
    pub fn current_reached(&self) -> bool {
        self.current_reached
    }

    /// Number of finalized cells.
    pub fn finalized_count(&self) -> usize {
        self.order.len()
    }

    /// Number of reached cells (finalized plus frontier).
    pub fn reached_count(&self) -> usize {
        self.touched.len()
    }
}

/// `G_Angle · G_Distance + S_Angle · S_Distance` of spec §3 step 4, from integer cell
/// offsets `v` = current → c and `w` = c → target, unit motion headings `hs`, `ht`, and the
/// path length `l` \[m\]. 0 where `SL` or `GL` is 0. Angles are in [0, π], computed as
/// `atan2(|v × h|, v · h)`, which needs no wrapping.
#[inline(always)]
fn posture_terms(
    vx: i64,
    vy: i64,
    wx: i64,
    wy: i64,
    hs: (f64, f64),
    ht: (f64, f64),
    l: f64,
) -> f64 {
    let (vx, vy, wx, wy) = (vx as f64, vy as f64, wx as f64, wy as f64);
    let sl2 = vx * vx + vy * vy;
    let gl2 = wx * wx + wy * wy;
    if sl2 == 0.0 || gl2 == 0.0 {
        return 0.0;
    }
    // G_Distance = SL / GL, S_Distance = (GL / SL) · L: only the ratio of the straight
    // distances is needed, so cells serve as the unit.
    let sl_over_gl = f64::sqrt(sl2 / gl2);
    let s_angle = atan2_nonneg((vx * hs.1 - vy * hs.0).abs(), vx * hs.0 + vy * hs.1);
    let g_angle = atan2_nonneg((wx * ht.1 - wy * ht.0).abs(), wx * ht.0 + wy * ht.1);
    g_angle * sl_over_gl + s_angle * l / sl_over_gl
}

fn validate(map: &GridMap, r: &FieldRequest) -> Result<(), LocalPathError> {
    for (what, (x, y)) in [("target", r.target), ("current", r.current)] {
        if x >= map.width() || y >= map.height() {
            return Err(LocalPathError::CellOutside {
                what,
                x,
                y,
                width: map.width(),
                height: map.height(),
            });
        }
    }
    if r.dmin.is_nan() || r.dmin < 0.0 {
        return Err(LocalPathError::BadParameter {
            name: "dmin",
            value: r.dmin,
            range: "[0, ∞)",
        });
    }
    let pcl = r.posture_consideration_level;
    if !(0.0..=100.0).contains(&pcl) {
        return Err(LocalPathError::BadParameter {
            name: "PostureConsiderationLevel",
            value: pcl,
            range: "[0, 100]",
        });
    }
    for (name, v) in [
        ("current heading", r.current_heading),
        ("target heading", r.target_heading),
    ] {
        if !v.is_finite() {
            return Err(LocalPathError::NotFinite {
                call: "PotentialField",
                argument: name,
                value: v,
            });
        }
    }
    Ok(())
}
