//! The TypeScript declarations of what a user interface reads from the core
//! (`web/types/core.d.ts`), made from the Rust view types themselves (`ts_rs::TS`, the
//! feature `typescript`). The page's JavaScript is type-checked against them
//! (`cargo xtask test`, stage "the page's types"), so a field renamed here fails there.
//!
//! `RTNAV_WRITE_TYPES=1 cargo test -p rtnav --features typescript --test typescript` writes
//! the file (`cargo xtask types` does so); without it the test fails when the file is not
//! what the types give.
#![cfg(feature = "typescript")]

use std::collections::BTreeMap;
use std::path::Path;

use rtnav::ErrorDetail;
use rtnav::render::Layers;
use rtnav::system::{
    CellInspection, ComparePlots, CompareTable, ComponentParameters, ExerciseView, FrameView,
    MapView, PlanView, PlotWindow, Refusal, ReplayCheck, ScenarioView, SystemGraph, TimelineView,
};
use ts_rs::{Config, TS, TypeVisitor};

/// Every declaration reached from the types visited, by name.
struct Declarations {
    cfg: Config,
    found: BTreeMap<String, String>,
}

impl TypeVisitor for Declarations {
    fn visit<T: TS + 'static + ?Sized>(&mut self) {
        if T::output_path().is_none() {
            return;
        }
        let name = T::ident(&self.cfg);
        if self.found.contains_key(&name) {
            return;
        }
        let docs = T::docs().unwrap_or_default();
        self.found
            .insert(name, format!("{docs}{}", T::decl(&self.cfg)));
        T::visit_dependencies(self);
    }
}

/// The file's text: every view type the page receives and every type they name, as global
/// declarations (the page's plain ES modules name them in JSDoc without an import).
fn declarations() -> String {
    // Every integer crosses as a JSON number (all of them are far below 2⁵³).
    let mut d = Declarations {
        cfg: Config::new().with_large_int("number"),
        found: BTreeMap::new(),
    };
    d.visit::<FrameView>();
    d.visit::<PlanView>();
    d.visit::<MapView>();
    d.visit::<ScenarioView>();
    d.visit::<Layers>();
    d.visit::<ComponentParameters>();
    d.visit::<PlotWindow>();
    d.visit::<CellInspection>();
    d.visit::<SystemGraph>();
    d.visit::<ExerciseView>();
    d.visit::<TimelineView>();
    d.visit::<ReplayCheck>();
    d.visit::<CompareTable>();
    d.visit::<ComparePlots>();
    d.visit::<ErrorDetail>();
    d.visit::<Refusal>();
    let mut out = String::from(
        "// The core's view types as the page receives them, written from the Rust types by\n\
         // `cargo xtask types` (core/tests/typescript.rs). Do not edit: change the Rust type.\n",
    );
    for decl in d.found.values() {
        out.push('\n');
        out.push_str(decl.trim_end());
        out.push('\n');
    }
    out
}

#[test]
fn the_page_s_declarations_are_those_of_the_rust_types() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../web/types/core.d.ts");
    let text = declarations();
    assert!(text.contains("type FrameView = {"), "{text}");
    if std::env::var_os("RTNAV_WRITE_TYPES").is_some() {
        std::fs::write(&path, &text).unwrap();
        return;
    }
    let written = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        written == text,
        "{} is not what the Rust types give: run `cargo xtask types`",
        path.display()
    );
}
