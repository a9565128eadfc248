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
//! Buffers are reused between plans: only the cells touched by the previous plan are reset,
//! plus one pass over the obstacle distances to mark impassable cells.

use serde::{Deserialize, Serialize};

use super::radix_queue::RadixQueue;
use crate::errors::LocalPathError;
use crate::interfaces::Direction;
use crate::map::{Cell, GridMap};

/// The potential of the local target (000 §5.2.4.9: "ポテンシャル値(0.1)を設定").
pub const TARGET_POTENTIAL: f64 = 0.1;

/// The 8-neighbour offsets (000 §5.2.4.9 ※1 "８連結") in the order a finalized cell assigns
/// its neighbours: counter-clockwise from +x. Ties in `G` are broken by this order.
pub const NEIGHBOURS: [(i64, i64); 8] = [
    (1, 0),
    (1, 1),
    (0, 1),
    (-1, 1),
    (-1, 0),
    (-1, -1),
    (0, -1),
    (1, -1),
];

const NO_PARENT: u8 = u8::MAX;
const NOT_FINAL: u32 = u32::MAX;

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
    /// From the byte of [`PotentialField::state_codes`].
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

/// One cell of the field: the potential, its three parts and the path length.
///
/// `#[repr(C)]`, 48 bytes: the five numbers are the first five `f64`s, so a browser can read
/// e.g. the potentials through one `Float64Array` over [`PotentialField::cells`] with a
/// stride of 6. Everything is 0 on impassable and unreached cells. Kept together because
/// the field touches all of them at once: one cache line per cell instead of five.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[repr(C)]
pub struct FieldCell {
    /// Potential `G`.
    pub potential: f64,
    /// Repulsion `R = 1 / (d − dmin)²`.
    pub repulsion: f64,
    /// Attraction `A = L · (100 − PCL) / 100`.
    pub attraction: f64,
    /// Posture `P`.
    pub posture: f64,
    /// Path length `L` to the target along the parents \[m\].
    pub length: f64,
    rank: u32,
    parent: u8,
}

impl FieldCell {
    const EMPTY: Self = Self {
        potential: 0.0,
        repulsion: 0.0,
        attraction: 0.0,
        posture: 0.0,
        length: 0.0,
        rank: NOT_FINAL,
        parent: NO_PARENT,
    };
}

/// The potential field "PotentialMap[][]" of 000 §5.2.4.9: the map's size, one
/// [`FieldCell`] and one [`CellState`] per cell (x fastest, as the map).
#[derive(Debug, Clone, Default)]
pub struct PotentialField {
    width: usize,
    height: usize,
    grid_size: f64,
    cells: Vec<FieldCell>,
    state: Vec<u8>,
    /// Cells assigned by the last computation, in assignment order (reset on the next).
    touched: Vec<u32>,
    /// The Dijkstra queue: potential bits, ties in assignment order.
    queue: RadixQueue,
    request: Option<FieldRequest>,
    finalized: usize,
    complete: bool,
    current_reached: bool,
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
        validate(map, request)?;
        self.reset(map, request);
        let w = self.width;
        let target = map.index(request.target);
        if self.state[target] == CellState::Impassable as u8 {
            return Err(LocalPathError::TargetBlocked {
                from: request.target,
            });
        }
        self.grow(map, request);
        if self.current_reached {
            Ok(())
        } else {
            debug_assert!(w > 0);
            Err(LocalPathError::NoRoute {
                target: request.target,
                current: request.current,
            })
        }
    }

    fn reset(&mut self, map: &GridMap, request: &FieldRequest) {
        let n = map.width() * map.height();
        if self.width != map.width() || self.height != map.height() || self.cells.len() != n {
            self.width = map.width();
            self.height = map.height();
            self.cells = vec![FieldCell::EMPTY; n];
            self.state = vec![0; n];
        } else {
            for &i in &self.touched {
                self.cells[i as usize] = FieldCell::EMPTY;
            }
        }
        self.touched.clear();
        self.queue.clear();
        self.grid_size = map.grid_size();
        let dmin = request.dmin;
        for (s, &d) in self.state.iter_mut().zip(map.distances()) {
            *s = if crate::map::within_dmin(d, dmin) {
                CellState::Impassable as u8
            } else {
                CellState::Unreached as u8
            };
        }
        self.request = Some(*request);
        self.finalized = 0;
        self.complete = false;
        self.current_reached = false;
    }

    /// Dijkstra growth from the target (000 §5.2.4.9, spec §3 step 4).
    fn grow(&mut self, map: &GridMap, req: &FieldRequest) {
        let (w, h) = (self.width as i64, self.height as i64);
        let g = map.grid_size();
        let dist = map.distances();
        let dmin = req.dmin;
        let step_straight = g;
        let step_diagonal = f64::sqrt(2.0) * g;
        let attraction_factor = (100.0 - req.posture_consideration_level) / 100.0;
        let posture_factor = req.posture_consideration_level / 100.0;
        let posture_on = req.posture && posture_factor > 0.0;
        let turn = match req.direction {
            Direction::Forward => 0.0,
            Direction::Backward => core::f64::consts::PI,
        };
        // Unit vectors of the motion headings at the current position and at the target.
        let hs = (
            libm::cos(req.current_heading + turn),
            libm::sin(req.current_heading + turn),
        );
        let ht = (
            libm::cos(req.target_heading + turn),
            libm::sin(req.target_heading + turn),
        );
        let (sx, sy) = (req.current.0 as i64, req.current.1 as i64);
        let (tx, ty) = (req.target.0 as i64, req.target.1 as i64);
        let current = map.index(req.current);
        let target = map.index(req.target);

        self.cells[target].potential = TARGET_POTENTIAL;
        self.state[target] = CellState::Reached as u8;
        self.touched.push(target as u32);
        self.queue.push(TARGET_POTENTIAL.to_bits(), target as u32);
        let unreached = CellState::Unreached as u8;
        let impassable = CellState::Impassable as u8;
        let reached = CellState::Reached as u8;

        while let Some((_, i)) = self.queue.pop() {
            let i = i as usize;
            self.cells[i].rank = self.finalized as u32;
            self.finalized += 1;
            if i == current {
                self.current_reached = true;
                if req.extent == FieldExtent::UntilCurrent {
                    break;
                }
            }
            let (px, py) = ((i % self.width) as i64, (i / self.width) as i64);
            let gp = self.cells[i].potential;
            let lp = self.cells[i].length;
            for (k, &(dx, dy)) in NEIGHBOURS.iter().enumerate() {
                let (nx, ny) = (px + dx, py + dy);
                if nx < 0 || ny < 0 || nx >= w || ny >= h {
                    continue;
                }
                let ni = (nx + ny * w) as usize;
                if self.state[ni] != unreached {
                    continue;
                }
                let diagonal = dx != 0 && dy != 0;
                if diagonal
                    && (self.state[(px + dx + py * w) as usize] == impassable
                        || self.state[(px + (py + dy) * w) as usize] == impassable)
                {
                    // A diagonal step may not cut the corner of an impassable cell.
                    continue;
                }
                let l = lp
                    + if diagonal {
                        step_diagonal
                    } else {
                        step_straight
                    };
                let clearance = dist[ni] - dmin;
                let r = 1.0 / (clearance * clearance);
                let a = l * attraction_factor;
                let p = if posture_on {
                    posture_factor * posture_terms(nx - sx, ny - sy, tx - nx, ty - ny, hs, ht, l)
                } else {
                    0.0
                };
                let gn = gp + r + a + p;
                self.cells[ni] = FieldCell {
                    potential: gn,
                    repulsion: r,
                    attraction: a,
                    posture: p,
                    length: l,
                    rank: NOT_FINAL,
                    parent: k as u8,
                };
                self.state[ni] = reached;
                self.touched.push(ni as u32);
                self.queue.push(gn.to_bits(), ni as u32);
            }
        }
        self.complete = self.queue.is_empty();
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

    /// Every cell's potential, parts and length, x fastest.
    pub fn cells(&self) -> &[FieldCell] {
        &self.cells
    }

    /// The potential of a cell (0 unless reached, and outside the field).
    pub fn potential(&self, cell: Cell) -> f64 {
        self.flat(cell).map_or(0.0, |i| self.cells[i].potential)
    }

    /// [`CellState`] per cell as bytes (0 unreached, 1 reached, 2 impassable), for a typed
    /// view in the browser.
    pub fn state_codes(&self) -> &[u8] {
        &self.state
    }

    fn flat(&self, (x, y): Cell) -> Option<usize> {
        (x < self.width && y < self.height).then_some(x + y * self.width)
    }

    /// The state of a cell (`Unreached` for a cell outside the field).
    pub fn state(&self, cell: Cell) -> CellState {
        self.flat(cell).map_or(CellState::Unreached, |i| {
            CellState::from_code(self.state[i])
        })
    }

    /// The neighbour a reached cell got its potential from (`None` for the target and
    /// cells not reached).
    pub fn parent(&self, cell: Cell) -> Option<Cell> {
        let i = self.flat(cell)?;
        let k = *NEIGHBOURS.get(self.cells[i].parent as usize)?;
        Some((
            (cell.0 as i64 - k.0) as usize,
            (cell.1 as i64 - k.1) as usize,
        ))
    }

    /// A cell's place in the finalization order, if it was finalized.
    pub fn rank(&self, cell: Cell) -> Option<u32> {
        let i = self.flat(cell)?;
        let rank = self.cells[i].rank;
        (rank != NOT_FINAL).then_some(rank)
    }

    /// The key the descent compares: `(G, finalization order)`; cells assigned but not
    /// finalized (the frontier of a stopped field) come after every finalized cell of equal
    /// potential. `None` unless reached.
    pub fn key(&self, cell: Cell) -> Option<(f64, u32)> {
        let i = self.flat(cell)?;
        (self.state[i] == CellState::Reached as u8)
            .then(|| (self.cells[i].potential, self.cells[i].rank))
    }

    /// Everything about one cell, for the GUI's inspector; `None` outside the field.
    pub fn info(&self, cell: Cell) -> Option<CellInfo> {
        let i = self.flat(cell)?;
        let c = &self.cells[i];
        Some(CellInfo {
            cell,
            state: CellState::from_code(self.state[i]),
            potential: c.potential,
            repulsion: c.repulsion,
            attraction: c.attraction,
            posture: c.posture,
            length: c.length,
            parent: self.parent(cell),
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
        self.finalized
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
    let s_angle = libm::atan2((vx * hs.1 - vy * hs.0).abs(), vx * hs.0 + vy * hs.1);
    let g_angle = libm::atan2((wx * ht.1 - wy * ht.0).abs(), wx * ht.0 + wy * ht.1);
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
