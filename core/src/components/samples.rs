//! How the data of the components' ports beyond the IDL types describe themselves for people
//! ([`Sample`]): the LocalPath service's arguments, its consumers' data, the map messages and
//! the bump report.

use crate::interfaces::{ControlPoints, GlobalPathCourse, GridPath, PlanningFailure};
use crate::map::MapUpdate;
use crate::motion::BumpReport;
use crate::present::number;
use crate::rtc::{Sample, Time, short};

use super::SetMapMessage;

impl Sample for SetMapMessage {
    const IDL: &'static str = "SetMap";
    fn tm(&self) -> Option<Time> {
        Some(self.tm)
    }
    fn fields(&self) -> String {
        format!(
            "MapLengthX: {}, MapLengthY: {}, GridSize: {}, load: {}",
            self.map.width(),
            self.map.height(),
            number(self.map.grid_size()),
            self.load
        )
    }
}

impl Sample for MapUpdate {
    const IDL: &'static str = "MapUpdate";
    fn tm(&self) -> Option<Time> {
        Some(self.tm)
    }
    fn fields(&self) -> String {
        let obstacles = self.value.iter().filter(|v| **v != 0).count();
        format!(
            "num: {} ({obstacles} obstacle, {} free)",
            self.num,
            self.value.len() - obstacles
        )
    }
}

impl Sample for GlobalPathCourse {
    const IDL: &'static str = "GlobalPathCourse";
    fn tm(&self) -> Option<Time> {
        None
    }
    fn fields(&self) -> String {
        let end = |i: Option<usize>| {
            i.and_then(|i| Some((self.grid_path_x.get(i)?, self.grid_path_y.get(i)?)))
                .map_or_else(|| "-".to_owned(), |(x, y)| format!("({x}, {y})"))
        };
        format!(
            "num: {}, from {} to {}",
            self.num,
            end(Some(0)),
            end(self.grid_path_x.len().checked_sub(1))
        )
    }
}

impl Sample for ControlPoints {
    const IDL: &'static str = "ControlPoints";
    fn tm(&self) -> Option<Time> {
        Some(self.tm)
    }
    fn fields(&self) -> String {
        let last = self.points.last().map_or_else(
            || "-".to_owned(),
            |p| format!("({}, {})", short(p.0), short(p.1)),
        );
        format!(
            "points: {}, last: {last}, direction: {:?}",
            self.points.len(),
            self.direction
        )
    }
}

impl Sample for GridPath {
    const IDL: &'static str = "GridPath";
    fn tm(&self) -> Option<Time> {
        Some(self.tm)
    }
    fn fields(&self) -> String {
        format!("cells: {}", self.cells.len())
    }
}

impl Sample for PlanningFailure {
    const IDL: &'static str = "PlanningFailure";
    fn tm(&self) -> Option<Time> {
        Some(self.tm)
    }
    fn fields(&self) -> String {
        format!("planner: {}, reason: {}", self.planner, self.reason)
    }
}

impl Sample for BumpReport {
    const IDL: &'static str = "BumpReport";
    fn tm(&self) -> Option<Time> {
        Some(self.tm)
    }
    fn fields(&self) -> String {
        format!(
            "cell: ({}, {}), speed: {}",
            self.cell.0,
            self.cell.1,
            short(self.speed)
        )
    }
}
