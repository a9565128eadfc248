//! What a request may not do to the robot's body (spec §5 "Physics", Decisions 0.4): set
//! it moving before it has a pose (`NotPlaced`), or put an obstacle under it
//! (`UnderRobot`). Checked before [`System::apply`](super::robot::System::apply) carries a
//! request out, so a refused one changes nothing.

use super::mission::Mission;
use super::wiring::Wiring;
use crate::rtc::LifecycleState;
use crate::system::vocabulary::error::SystemError;
use crate::system::vocabulary::input::Input;
use crate::system::vocabulary::kind::ComponentKind;

/// Refuses `input` if it may not be carried out on the robot of `wiring` and `mission`:
/// the robot has no pose until a start is placed, so PhysicsSim is not activated before
/// (`Activate`, `ActivateAll`); and no `MapUpdate` makes a cell under the placed robot's
/// body an obstacle (the physics' own contact test, [`Physics::body_covers`]).
///
/// [`Physics::body_covers`]: crate::motion::Physics::body_covers
pub(super) fn check(input: &Input, wiring: &Wiring, mission: &Mission) -> Result<(), SystemError> {
    refusal(input, wiring, mission).map_or(Ok(()), Err)
}

fn refusal(input: &Input, wiring: &Wiring, mission: &Mission) -> Option<SystemError> {
    let placed = mission.start().is_some();
    let physics_inactive =
        wiring.component_state(ComponentKind::PhysicsSim) == LifecycleState::Inactive;
    match input {
        Input::Activate {
            component: ComponentKind::PhysicsSim,
        } if !placed && physics_inactive => Some(SystemError::NotPlaced { call: "Activate" }),
        Input::ActivateAll if !placed && physics_inactive => Some(SystemError::NotPlaced {
            call: "ActivateAll",
        }),
        Input::MapUpdate { cells } if placed => {
            let map = wiring.map()?;
            let body = wiring.physics().physics();
            cells
                .iter()
                .find(|&&(x, y, v)| {
                    v == 1 && map.contains(x, y) && !map.is_obstacle(x, y) && body.body_covers(x, y)
                })
                .map(|&(x, y, _)| SystemError::UnderRobot { x, y })
        }
        _ => None,
    }
}
