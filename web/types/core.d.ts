// The core's view types as the page receives them, written from the Rust types by
// `cargo xtask types` (core/tests/typescript.rs). Do not edit: change the Rust type.

/**
 * A bump (spec §5 "touching an obstacle cell is a bump"): who hit what, where, when.
 */
type BumpReport = { 
/**
 * Simulated time of the bump.
 */
tm: Time, 
/**
 * The robot ([`PhysicsParams::robot_name`]).
 */
who: string, 
/**
 * Where the robot stopped (axle-centre pose).
 */
pose: Pose, 
/**
 * The obstacle cell touched (may lie outside the map, which counts as obstacle).
 */
cell: [number, number], 
/**
 * The point of the cell nearest the body's centre \[m\].
 */
contact: [number, number], 
/**
 * Body speed when it hit \[m/s\].
 */
speed: number, };

/**
 * Everything about one map cell, as the inspector shows it (JSON: `{x, y, occupancy,
 * obstacle_distance, impassable, field}`).
 */
type CellInspection = { 
/**
 * Column.
 */
x: number, 
/**
 * Row.
 */
y: number, 
/**
 * The cell's centre in the map's world frame \[m\] (spec §2: `origin + (i + ½)·g`).
 */
centre: [number, number], 
/**
 * The map's value: 0 free, 1 obstacle (spec §2).
 */
occupancy: number, 
/**
 * Metres from the cell's centre to the nearest obstacle cell's centre (spec §2; 0 on an
 * obstacle cell).
 */
obstacle_distance: number, 
/**
 * Whether the cell is within LocalPathPlanning's effective `dmin` of an obstacle
 * ([`map::within_dmin`], spec §3 step 4: impassable).
 */
impassable: boolean, 
/**
 * The potential field's view of the cell; `None` while LocalPathPlanning has no field
 * for this map.
 */
field: FieldInspection | null, };

/**
 * One check of an exercise.
 */
type Check = { "check": "arrived", 
/**
 * Seconds.
 */
within_s: number, } | { "check": "no_bump" } | { "check": "arrival_heading", 
/**
 * Degrees.
 */
within_deg: number, } | { "check": "approach_heading", 
/**
 * Degrees.
 */
within_deg: number, } | { "check": "min_clearance", 
/**
 * Metres.
 */
at_least_m: number, } | { "check": "max_replans", 
/**
 * Plans.
 */
at_most: number, } | { "check": "min_replans", 
/**
 * Plans.
 */
at_least: number, } | { "check": "min_global_plans", 
/**
 * Plans.
 */
at_least: number, } | { "check": "reach_speed", 
/**
 * \[m/s\].
 */
speed: number, 
/**
 * Seconds.
 */
within_s: number, 
/**
 * Percent of `speed`.
 */
band_percent: number, } | { "check": "max_overshoot", 
/**
 * \[m/s\].
 */
speed: number, 
/**
 * Percent of `speed`.
 */
at_most_percent: number, } | { "check": "backward_distance", 
/**
 * Metres.
 */
at_least_m: number, } | { "check": "max_localization_error", 
/**
 * Metres.
 */
at_most_m: number, } | { "check": "max_localization_heading_error", 
/**
 * Degrees.
 */
at_most_deg: number, } | { "check": "recovered" } | { "check": "only_allowed" } | { "check": "no_warning" };

/**
 * Where a check stands.
 */
type CheckState = "open" | "passed" | "failed";

/**
 * One check as it stands (the page's checklist line, `rtnav check`'s line).
 */
type CheckStatus = { 
/**
 * The check and its numbers.
 */
check: Check, 
/**
 * Where it stands.
 */
state: CheckState, 
/**
 * What was measured so far, in [`CheckStatus::unit`]; `None` when nothing yet.
 */
measured: number | null, 
/**
 * The unit of `measured` ([`Check::unit`]).
 */
unit: Unit | null, 
/**
 * For [`Check::OnlyAllowed`]: the parameters changed that may not be
 * (`Component.Parameter`).
 */
changed: Array<string>, 
/**
 * For [`Check::NoWarning`]: the parameters in use that the page warns about
 * (`Component.Parameter`).
 */
warned: Array<string>, };

/**
 * The clock as the system bar shows it.
 */
type ClockView = { 
/**
 * Simulated time \[s\].
 */
time_s: number, 
/**
 * Simulated time owed to the clock and not yet run \[s\].
 */
behind_s: number, 
/**
 * Whether the clock is paused.
 */
paused: boolean, 
/**
 * Simulated seconds per wall second.
 */
speed: number, 
/**
 * One base tick \[s\] (a step of ±1 tick).
 */
tick_s: number, };

/**
 * Speeds over time of both runs (the overlaid plots).
 */
type ComparePlots = { 
/**
 * Time since the activation, run A \[s\].
 */
t_a: Array<number>, 
/**
 * Speed, run A \[m/s\].
 */
v_a: Array<number>, 
/**
 * Turn rate, run A \[rad/s\].
 */
w_a: Array<number>, 
/**
 * Time since the activation, run B \[s\].
 */
t_b: Array<number>, 
/**
 * Speed, run B \[m/s\].
 */
v_b: Array<number>, 
/**
 * Turn rate, run B \[rad/s\].
 */
w_b: Array<number>, };

/**
 * The compare view's table.
 */
type CompareTable = { 
/**
 * The scenario.
 */
scenario: string, 
/**
 * `[measure, A, B]` in words.
 */
rows: Array<[string, string, string]>, 
/**
 * Run A's measures.
 */
a: RunSummary, 
/**
 * Run B's measures.
 */
b: RunSummary, };

/**
 * What a component is doing or holds (see the module documentation).
 */
type ComponentActivity = { "kind": "in_error", 
/**
 * The reason of its last failure, if one is known.
 */
reason: Reason | null, } | { "kind": "inactive" } | { "kind": "map", 
/**
 * Cells in x.
 */
width: number, 
/**
 * Cells in y.
 */
height: number, 
/**
 * `GridSize` \[m\].
 */
grid_size: number, } | { "kind": "no_map" } | { "kind": "updates_sent", 
/**
 * How many.
 */
updates: number, } | { "kind": "bumps", 
/**
 * How many.
 */
bumps: number, 
/**
 * Whether it touches an obstacle now.
 */
touching: boolean, } | { "kind": "waiting_for", 
/**
 * The in-ports that have not received a sample yet.
 */
inputs: Array<string>, } | { "kind": "running" } | { "kind": "stopped" } | { "kind": "finished" } | { "kind": "safe_stop", 
/**
 * What it holds at zero: `torque` (MotorControl) or `velocity` (DriveControl).
 */
output: ZeroOutput, 
/**
 * Why.
 */
reason: Reason, } | { "kind": "localizing", 
/**
 * `SimulatedPose` or `Odometry`.
 */
mode: LocalizationMode, } | { "kind": "route_failed", 
/**
 * Why.
 */
reason: Reason, } | { "kind": "route", 
/**
 * Its length \[m\].
 */
length: number, } | { "kind": "no_route" } | { "kind": "local_planning", 
/**
 * The held flags that are set.
 */
holds: Array<Held>, 
/**
 * Local plans made (potential fields computed).
 */
made: number, 
/**
 * Local plans sent (the same figure as the telemetry's "local plans sent": the
 * record's count of them).
 */
sent: number, 
/**
 * Whether it waits to try again after a failure (Active only).
 */
retrying: boolean, } | { "kind": "waiting_for_pose" } | { "kind": "idle" } | { "kind": "turning_on_the_spot" } | { "kind": "following_path" } | { "kind": "turning_to_goal_heading" } | { "kind": "arrived" } | { "kind": "safety_stop", 
/**
 * Free travel left along the commanded arc \[m\].
 */
ahead: number, } | { "kind": "script", 
/**
 * The script's name (a file name).
 */
script: string, 
/**
 * Whether it is Active (its actions run every period).
 */
active: boolean, };

/**
 * One of the system's components (spec §0). The order of [`ComponentKind::ALL`] is the
 * attachment order, which is the order they run in a tick (see `crate::system`).
 */
type ComponentKind = "MapBuilder" | "MapMaintenance" | "PhysicsSim" | "MotorControl" | "Localization" | "GlobalPathPlanning" | "LocalPathPlanning" | "DriveControl";

/**
 * One component's parameters (the parameter panel's group).
 */
type ComponentParameters = { 
/**
 * The component (`LocalPathPlanning`).
 */
component: string, 
/**
 * Its instance name (`LocalPathPlanning0`).
 */
instance_name: string, 
/**
 * Its execution period \[s\] (MotorControl's `Δt` in the note on its gains, spec §4).
 */
period_s: number, 
/**
 * Its parameters in declaration order.
 */
params: Array<ParameterView>, };

/**
 * One component as the RTC panel shows it.
 */
type ComponentView = { 
/**
 * The component's name (`LocalPathPlanning`): what the lifecycle calls take.
 */
name: string, 
/**
 * The RT System Editor's colour of its state, `#rrggbb`.
 */
colour: string, 
/**
 * Whether an injected fault waits for its next execution.
 */
fault_pending: boolean, 
/**
 * Which component.
 */
kind: ComponentKind, 
/**
 * Its instance name.
 */
instance_name: string, 
/**
 * Its lifecycle state.
 */
state: LifecycleState, 
/**
 * Its rate \[Hz\].
 */
rate: number, 
/**
 * The reason of its last callback failure (kept until a reset succeeds).
 */
last_error: Reason | null, 
/**
 * What it is doing or holds ([`ComponentActivity`]).
 */
status: ComponentActivity, };

/**
 * Data or service.
 */
type ConnectionKind = "data" | "service";

/**
 * What decided an exercise's verdict (spec §7 Decision 0.4).
 */
type DecidedBy = { 
/**
 * The check that decided it: its index in [`ExerciseStatus::checks`].
 */
check: number, 
/**
 * Why the run, left alone, cannot pass while that check is still open; `None` when
 * the check failed for good.
 */
stuck: Stuck | null, };

/**
 * `forward` / `backward`.
 */
type DirectionView = "forward" | "backward";

/**
 * One end of a connection.
 */
type Endpoint = { 
/**
 * The component's name.
 */
component: string, 
/**
 * The port's name.
 */
port: string, };

/**
 * An error as data, for a GUI that says it in its own language: the area (the variant of
 * [`Error`], `Lifecycle`), the kind (the area enum's variant, `InvalidTransition`) and its
 * named fields as the enum holds them (`{"component": "DriveControl", "from": "Inactive",
 * "request": "Deactivate"}`). The English words stay the error's `Display`.
 */
type ErrorDetail = { 
/**
 * The [`Error`] variant: `Lifecycle`, `Config`, `Map`, ….
 */
area: string, 
/**
 * The area enum's variant (`Timestamp`'s one kind is `Invalid`).
 */
kind: string, 
/**
 * The variant's named fields (an object; empty for a variant without fields).
 */
fields: Record<string, unknown>, };

/**
 * How the event log colours an event.
 */
type EventLevel = "info" | "state" | "success" | "warn" | "error";

/**
 * One entry of the event log.
 */
type EventView = { 
/**
 * Simulated time \[s\].
 */
time_s: number, 
/**
 * The event's kind (`GlobalPlan`, `Bump`, …).
 */
kind: string, 
/**
 * How the log colours it.
 */
level: EventLevel, 
/**
 * The event's fields (`null` for a kind without fields).
 */
data: Record<string, unknown> | null, };

/**
 * The scenario's exercise as the page's panel shows it: what the watch decided, and the
 * session's clock, so the panel never says the drive runs while the clock stands still.
 */
type ExerciseView = { 
/**
 * Whether the session's clock is paused: an exercise waiting or running goes on only
 * when it runs.
 */
paused: boolean, 
/**
 * The task.
 */
task: string, 
/**
 * The parameters that may be changed.
 */
may_change: Array<string>, 
/**
 * The actions expected.
 */
actions: Array<string>, 
/**
 * Each check, then the rules [`Check::OnlyAllowed`] and [`Check::NoWarning`] last.
 */
checks: Array<CheckStatus>, 
/**
 * The verdict.
 */
verdict: Verdict, 
/**
 * What decided a `Failed` verdict: the check that failed first, or the check that a
 * run left alone cannot pass and why; `None` otherwise.
 */
decided_by: DecidedBy | null, 
/**
 * When the drive started \[s of simulated time\].
 */
started_at: number | null, 
/**
 * When the exercise ended, counted from the drive's start \[s\].
 */
ended_after: number | null, };

/**
 * One cell of LocalPathPlanning's potential field (000 §5.2.4.9). The numbers are defined
 * on reached cells only (`None` elsewhere): `potential` is `G`, and for every reached cell
 * but the local target `G = G(parent) + repulsion + attraction + posture`; the target has
 * `G` = 0.1 and parts 0.
 */
type FieldInspection = { 
/**
 * Potential `G`.
 */
potential: number | null, 
/**
 * Repulsion `R = 1 / (d − dmin)²`.
 */
repulsion: number | null, 
/**
 * Attraction `A = L · (100 − PCL) / 100`.
 */
attraction: number | null, 
/**
 * Posture `P`.
 */
posture: number | null, 
/**
 * The neighbour the cell got its potential from (000 §5.2.4.9: the first finalized
 * 8-neighbour, the one with the lowest potential), with that potential `G(parent)`, so
 * that `G = G(parent) + R + A + P`; `None` for the local target and cells not reached.
 */
parent: ParentInspection | null, 
/**
 * Path length `L` from the local target along the parents \[m\].
 */
length: number | null, 
/**
 * The field's cell state: `Reached`, `Unreached` or `Impassable`
 * ([`CellState`]'s names).
 */
state: string, 
/**
 * Whether the cell is passable but was not reached (not connected to the local target,
 * or beyond where the field stopped).
 */
unreached: boolean, };

/**
 * One frame's read of the session: everything the page shows every frame, read once and
 * handed to its panels.
 */
type FrameView = { 
/**
 * The clock.
 */
clock: ClockView, 
/**
 * The telemetry and the status.
 */
telemetry: TelemetryView, 
/**
 * Every component, in data-flow order.
 */
components: Array<ComponentView>, 
/**
 * The events since the last frame, oldest first.
 */
events: Array<EventView>, 
/**
 * The scenario's exercise as it stands (`null` when it has none).
 */
exercise: ExerciseView | null, };

/**
 * One box of the picture.
 */
type GraphComponent = { 
/**
 * `MotorControl`, or `InventGUI`.
 */
name: string, 
/**
 * `MotorControl0` (InventGUI: `InventGUI`).
 */
instance_name: string, 
/**
 * Whether it is an RT-component (InventGUI is the person's side: the page, the
 * command line, a scenario's timeline).
 */
rtc: boolean, 
/**
 * Its lifecycle state (`Inactive`, `Active`, `Error`); none for InventGUI.
 */
state: string | null, 
/**
 * Its execution rate \[Hz\]; none for InventGUI.
 */
rate_hz: number | null, 
/**
 * Its ports: data in, data out, services provided, services required.
 */
ports: Array<GraphPort>, 
/**
 * The student's script it runs (its name), if one stands in its place (spec §8).
 */
script: string | null, };

/**
 * One line of the picture.
 */
type GraphConnection = { 
/**
 * `DriveControl.TargetVelocity->MotorControl.TargetVelocity`: what
 * `Input::CutConnection` names.
 */
id: string, 
/**
 * Data or service.
 */
kind: ConnectionKind, 
/**
 * The out-port or the caller's port.
 */
from: Endpoint, 
/**
 * The in-port or the provided port.
 */
to: Endpoint, 
/**
 * The IDL type or the interface.
 */
interface: string, 
/**
 * Samples it carried, or calls made through it.
 */
carried: number, 
/**
 * Whether it is cut now.
 */
cut: boolean, 
/**
 * Whether it may be cut (a data connection between two components).
 */
cuttable: boolean, };

/**
 * One port marker on a box.
 */
type GraphPort = { 
/**
 * Its name (the seeds' where they name it).
 */
name: string, 
/**
 * In, out, provided or required.
 */
kind: PortKind, 
/**
 * The IDL type (data) or the interface (service).
 */
interface: string, 
/**
 * The operations called on a provided port.
 */
operations: Array<string>, 
/**
 * Samples through a data port; calls on a provided port.
 */
count: number, 
/**
 * The newest sample, or the last call (`SetPDGain(5, 5, 2, 2)`) with its time.
 */
last: SampleView | null, };

/**
 * One of LocalPathPlanning's held flags (000 §5.2.4) that the RTC panel lists.
 */
type Held = "map" | "start_and_goal" | "path" | "arrived" | "safe_mode";

/**
 * Which layers to draw. Every layer is on by default; in serde form a missing field is on.
 */
type Layers = { 
/**
 * Obstacle cells.
 */
occupancy: boolean, 
/**
 * Cells within `dmin` of an obstacle (000 §5.2.4.2), tinted.
 */
dmin_zone: boolean, 
/**
 * The potential field, log scale, with its colour bar.
 */
heat_map: boolean, 
/**
 * The global path (GlobalPathPlanning's `GlobalPathCourse`).
 */
global_path: boolean, 
/**
 * The merged local path (000 §5.2.4.11).
 */
local_path: boolean, 
/**
 * The control points (000 §5.2.4.12).
 */
control_points: boolean, 
/**
 * The local target (000 §5.2.4.8).
 */
local_target: boolean, 
/**
 * The robot body, heading and wheels.
 */
robot: boolean, 
/**
 * Where the robot has been.
 */
trail: boolean, 
/**
 * Start and goal arrows (`SetPosition`).
 */
start_goal: boolean, 
/**
 * The scale bar.
 */
scale_bar: boolean, 
/**
 * The legend of the layers shown.
 */
legend: boolean, 
/**
 * The driving direction and the caption text.
 */
caption: boolean, };

/**
 * A component's lifecycle state (003 "コンポーネント・ライフサイクル").
 *
 * `Inactive`, `Active` and `Error` are the three sub-states of `Alive`; the RT System Editor
 * draws them blue, green and red.
 */
type LifecycleState = "Created" | "Inactive" | "Active" | "Error" | "Finalized";

/**
 * Where the published pose comes from (`LocalizationMode`).
 */
type LocalizationMode = "SimulatedPose" | "Odometry";

/**
 * The map's geometry.
 */
type MapView = { 
/**
 * The scenario's map file or the file the user loaded.
 */
name: string, 
/**
 * Cells along x.
 */
width: number, 
/**
 * Cells along y.
 */
height: number, 
/**
 * Cell size \[m\].
 */
grid_size: number, 
/**
 * The world point of the map's corner `[x, y]` \[m\].
 */
origin: [number, number], 
/**
 * Obstacle cells.
 */
obstacles: number, 
/**
 * Changes with every load and update.
 */
key: number, };

/**
 * Something that happened, marked on the timeline.
 */
type Mark = { 
/**
 * Simulated time \[ns\].
 */
t_ns: number, 
/**
 * What.
 */
kind: MarkKind, 
/**
 * The event marked (its kind and fields, said by the page as its log says it).
 */
event: EventView, };

/**
 * What a mark on the timeline stands for.
 */
type MarkKind = "plan" | "failure" | "bump" | "fault" | "arrival";

/**
 * How a run ended.
 */
type OutcomeKind = "arrived" | "stopped_off_goal" | "planning_failed" | "bumped" | "component_error" | "halted" | "time_limit";

/**
 * One parameter: its declaration (spec §1) and its values now.
 */
type ParameterView = { 
/**
 * The seed's name.
 */
name: string, 
/**
 * `double` or `int`.
 */
type: string, 
/**
 * Unit.
 */
unit: string, 
/**
 * Default.
 */
default: number, 
/**
 * Smallest allowed value; `None` for unbounded.
 */
min: number | null, 
/**
 * Largest allowed value; `None` for unbounded.
 */
max: number | null, 
/**
 * The range as text (`[0, 100]`).
 */
range: string, 
/**
 * `always` or `on_activation`.
 */
reflection: string, 
/**
 * What it means, in English.
 */
description: string, 
/**
 * The seed's own (Japanese) words for it, for the parameters of 000 and 002 §4.2.
 */
seed_text: string | null, 
/**
 * What the value in use does that a person should know (spec §4 note: gains that make
 * the wheel loop unstable or limp; spec §3 Decision 0.2: a `dmin` that lets the body
 * touch obstacles), as data; `None` when nothing.
 */
warning: ParameterWarning | null, 
/**
 * The requested value.
 */
value: number, 
/**
 * The value the component uses.
 */
effective: number, 
/**
 * Whether the requested value waits for the next activation.
 */
pending: boolean, };

/**
 * A parameter's warning (see the module documentation).
 */
type ParameterWarning = { "kind": "gain_unstable", 
/**
 * The P gain.
 */
p: number, 
/**
 * The D gain.
 */
d: number, 
/**
 * The bound `2·D/Δt`.
 */
bound: number, } | { "kind": "gain_limp", 
/**
 * The P gain.
 */
p: number, 
/**
 * The rate gain P alone gives, `P·Δt/2` \[N·m·s/rad\].
 */
rate_gain: number, } | { "kind": "clearance", 
/**
 * `dmin` \[m\].
 */
dmin: number, 
/**
 * The map's `GridSize` \[m\].
 */
grid_size: number, 
/**
 * MotorControl's `radiusOfBodyArea` \[m\].
 */
body_radius: number, };

/**
 * The parent of a reached cell in the potential field.
 */
type ParentInspection = { 
/**
 * Column.
 */
x: number, 
/**
 * Row.
 */
y: number, 
/**
 * Its potential `G(parent)`.
 */
potential: number, };

/**
 * The plan as data: start, goal, the paths in cells, the control points in metres.
 */
type PlanView = { 
/**
 * The start set, if any.
 */
start: PoseView | null, 
/**
 * The goal set, if any.
 */
goal: PoseView | null, 
/**
 * The driving direction.
 */
direction: DirectionView, 
/**
 * GlobalPathPlanning's route, cells `[x, y]`.
 */
global_path: Array<[number, number]>, 
/**
 * LocalPathPlanning's merged path, cells `[x, y]`.
 */
local_path: Array<[number, number]>, 
/**
 * The control points `[x, y]` \[m\].
 */
control_points: Array<[number, number]>, };

/**
 * The last seconds of telemetry as one array per series (what the plots draw).
 */
type PlotWindow = { 
/**
 * Simulated time \[s\].
 */
t: Array<number>, 
/**
 * MotorControl's target wheel rate, left \[rad/s\].
 */
target_rate_l: Array<number>, 
/**
 * MotorControl's target wheel rate, right \[rad/s\].
 */
target_rate_r: Array<number>, 
/**
 * The physics' wheel rate, left \[rad/s\].
 */
rate_l: Array<number>, 
/**
 * The physics' wheel rate, right \[rad/s\].
 */
rate_r: Array<number>, 
/**
 * MotorControl's torque, left \[N·m\].
 */
torque_l: Array<number>, 
/**
 * MotorControl's torque, right \[N·m\].
 */
torque_r: Array<number>, 
/**
 * The torque the physics applied, left \[N·m\] (saturated at `MaxTorque`).
 */
applied_l: Array<number>, 
/**
 * The torque the physics applied, right \[N·m\].
 */
applied_r: Array<number>, 
/**
 * PhysicsSim's `MaxTorque` now \[N·m\]: the saturation limit.
 */
max_torque: number, 
/**
 * DriveControl's commanded speed \[m/s\].
 */
v_cmd: Array<number>, 
/**
 * The robot's speed \[m/s\].
 */
v: Array<number>, 
/**
 * DriveControl's commanded turn rate \[rad/s\].
 */
w_cmd: Array<number>, 
/**
 * The robot's turn rate \[rad/s\].
 */
w: Array<number>, 
/**
 * DriveControl's deviation from the path \[m\]; `None` while it has no path.
 */
deviation: Array<number | null>, 
/**
 * LocalPathPlanning's `Deviatinglen` now \[m\].
 */
deviatinglen: number, 
/**
 * The times of global and local plans in the window \[s\].
 */
replans: Array<number>, };

/**
 * What a port is.
 */
type PortKind = "in" | "out" | "provided" | "required";

/**
 * A pose in the map frame: metres, and radians counter-clockwise from the X axis
 * (000 §5.2.4.2).
 */
type Pose = { 
/**
 * X in metres.
 */
x: number, 
/**
 * Y in metres.
 */
y: number, 
/**
 * Heading θ in radians.
 */
theta: number, };

/**
 * A pose with its heading in degrees (what a person reads).
 */
type PoseView = { 
/**
 * \[m\]
 */
x: number, 
/**
 * \[m\]
 */
y: number, 
/**
 * Heading, counter-clockwise from +x \[°\].
 */
theta_deg: number, };

/**
 * Why something failed or stopped (see the module documentation).
 */
type Reason = { "kind": "error", error: ErrorDetail, } | { "kind": "bump", report: BumpReport, } | { "kind": "injected_fault", words: string, } | { "kind": "course_refused", error: ErrorDetail, } | { "kind": "map_update_refused", component: string, error: ErrorDetail, } | { "kind": "obstacle_ahead", ahead: number, } | { "kind": "words", words: string, };

/**
 * A refused request: serialized as the detail the page reads (`{area, kind, fields,
 * file?, scenario?}`); the English words apart.
 */
type Refusal = { 
/**
 * The file the error is about.
 */
file?: string, 
/**
 * The scenario the error is about.
 */
scenario?: string, 
/**
 * The [`Error`] variant: `Lifecycle`, `Config`, `Map`, ….
 */
area: string, 
/**
 * The area enum's variant (`Timestamp`'s one kind is `Invalid`).
 */
kind: string, 
/**
 * The variant's named fields (an object; empty for a variant without fields).
 */
fields: Record<string, unknown>, };

/**
 * What loading a replay found: whether the run reproduced the recorded trace.
 */
type ReplayCheck = { 
/**
 * The scenario.
 */
scenario: string, 
/**
 * The recorded end \[ns\].
 */
end_ns: number, 
/**
 * Requests replayed.
 */
inputs: number, 
/**
 * The trace hash recorded in the file.
 */
expected_hash: string, 
/**
 * The trace hash of the run replayed.
 */
hash: string, 
/**
 * Telemetry samples recorded in the file.
 */
expected_samples: number, 
/**
 * Telemetry samples of the run replayed.
 */
samples: number, 
/**
 * Whether the two runs are the same (hash and samples).
 */
matches: boolean, };

/**
 * One run's measures (a column of the table).
 */
type RunSummary = { 
/**
 * The configuration in words (`PostureConsiderationLevel=85`, or `as written`).
 */
label: string, 
/**
 * How the run ended.
 */
outcome: OutcomeKind, 
/**
 * From the activation to the arrival \[s\]; `None` if it did not arrive.
 */
time_to_goal_s: number | null, 
/**
 * Distance the robot's centre drove \[m\].
 */
path_length_m: number, 
/**
 * Smallest distance from the robot's centre to an obstacle while driving \[m\].
 */
min_clearance_m: number, 
/**
 * Heading error when it reached the goal position, before the final turn \[°\];
 * `None` if it never did.
 */
arrival_heading_error_deg: number | null, 
/**
 * Heading error at the end \[°\].
 */
final_heading_error_deg: number, 
/**
 * Local plans made.
 */
replans: number, 
/**
 * Global plans sent.
 */
global_plans: number, 
/**
 * The wheels' mechanical work \[J\] (module documentation).
 */
energy_j: number, 
/**
 * Simulated time at the end \[s\].
 */
sim_time_s: number, 
/**
 * The trace hash.
 */
trace_hash: string, };

/**
 * The newest sample of a port, for people.
 */
type SampleView = { 
/**
 * Its timestamp \[s\], if it has one.
 */
tm: number | null, 
/**
 * `TimedVelocity {tm: 12.340 s, vx: 0.48, vy: 0, w: -0.12}`.
 */
text: string, };

/**
 * The scenario shown (name, description, the lesson's text).
 */
type ScenarioView = { 
/**
 * The scenario's name.
 */
name: string, 
/**
 * One line about it.
 */
description: string, 
/**
 * The lesson's text.
 */
lesson: string, };

/**
 * Why a run, left alone (nothing more asked of it than its scenario's timeline and
 * recorded requests), can no longer pass: the robot stands and nothing the system does on
 * its own moves it again (spec §7 Decision 0.4).
 */
type Stuck = { "kind": "component_error", 
/**
 * Its instance name.
 */
component: string, } | { "kind": "inactive", 
/**
 * Its instance name.
 */
component: string, } | { "kind": "no_route" } | { "kind": "stopped_off_goal" } | { "kind": "halted" };

/**
 * The whole system as RT System Editor would show it, at one moment.
 */
type SystemGraph = { 
/**
 * Simulated time \[s\].
 */
time: number, 
/**
 * InventGUI first, then the eight RT-components in data-flow order.
 */
components: Array<GraphComponent>, 
/**
 * Data connections as the wiring made them, then service connections.
 */
connections: Array<GraphConnection>, };

/**
 * The whole system's state, from its components' states.
 */
type SystemState = "Inactive" | "Active" | "Partial" | "Error";

/**
 * The telemetry readout: where the robot is, what it does, the run's counters.
 */
type TelemetryView = { 
/**
 * Simulated time \[s\].
 */
time_s: number, 
/**
 * The system's state.
 */
state: SystemState, 
/**
 * Whether the robot drives (a plan is being followed).
 */
driving: boolean, 
/**
 * Which [`Status`](crate::system::Status) it is (`driving`, `arrived`, `no_route`, …): what the
 * page ties its notices to.
 */
status_kind: string, 
/**
 * Its fields (`component`, `reason`, `by`, `direction`, `retrying`, `v_cmd`, …), so the
 * page can say the status in its own language with the same details; and `paused:
 * true` while the session's clock is paused (a cause the status says, `status.paused`).
 */
status_fields: Record<string, unknown>, 
/**
 * Whether the robot has arrived at the goal.
 */
arrived: boolean, 
/**
 * Whether the robot is halted (safe mode, a stop).
 */
halted: boolean, 
/**
 * Whether the clock is paused.
 */
paused: boolean, 
/**
 * Simulated seconds per wall second.
 */
speed: number, 
/**
 * The robot's pose.
 */
pose: PoseView, 
/**
 * The body's radius as drawn \[m\] (MotorControl's `radiusOfBodyArea` in use).
 */
body_radius: number, 
/**
 * The start set, if any.
 */
start: PoseView | null, 
/**
 * The goal set, if any.
 */
goal: PoseView | null, 
/**
 * The driving direction.
 */
direction: DirectionView, 
/**
 * Distance from the robot to the goal \[m\] (`null` without a goal).
 */
distance_to_goal: number | null, 
/**
 * Measured speed \[m/s\]: the physics' motion now (`Measured`), 0 while it does not
 * execute.
 */
v: number, 
/**
 * Measured turn rate \[rad/s\] (as `v`).
 */
w: number, 
/**
 * Commanded speed \[m/s\].
 */
v_cmd: number, 
/**
 * Commanded turn rate \[rad/s\].
 */
w_cmd: number, 
/**
 * Deviation from the path \[m\] (`null` while there is none).
 */
deviation: number | null, 
/**
 * Distance driven \[m\].
 */
path_length: number, 
/**
 * Global plans made.
 */
global_plans: number, 
/**
 * Local plans made.
 */
local_plans: number, 
/**
 * Plans that failed.
 */
planning_failures: number, 
/**
 * Bumps.
 */
bumps: number, 
/**
 * Smallest clearance to an obstacle so far \[m\] (`null` before the robot moved).
 */
min_clearance: number | null, };

/**
 * `RTC::Time`: seconds and nanoseconds.
 */
type Time = { 
/**
 * Whole seconds.
 */
sec: number, 
/**
 * Nanoseconds, `0..1_000_000_000`.
 */
nsec: number, };

/**
 * The timeline's read-out for the page.
 */
type TimelineView = { 
/**
 * Where the history starts (the set-up built) \[ns\].
 */
start_ns: number, 
/**
 * The session's time \[ns\].
 */
now_ns: number, 
/**
 * The furthest time known: simulated so far, or a loaded replay's end \[ns\].
 */
end_ns: number, 
/**
 * Requests recorded (applied and still to replay).
 */
inputs: number, 
/**
 * Requests still to replay.
 */
pending: number, 
/**
 * Checkpoints kept.
 */
checkpoints: number, 
/**
 * Their spacing \[ns\].
 */
checkpoint_ns: number, 
/**
 * Marks up to the furthest time simulated.
 */
marks: Array<Mark>, };

/**
 * The unit of a check's measured value.
 */
type Unit = "s" | "deg" | "m" | "plans" | "percent" | "m/s";

/**
 * How the exercise stands.
 */
type Verdict = "waiting" | "running" | "passed" | "failed";

/**
 * What a safe stop holds at zero.
 */
type ZeroOutput = "torque" | "velocity";
