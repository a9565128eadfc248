//! `rtnav render`: the initial plan of a scenario drawn, however many executions the map's
//! size needs for it.

use std::process::Command;

/// A scenario on a `side` × `side` yard (a wall around it) whose LocalPathPlanning runs at
/// 1 Hz, written into `dir`: the set-up's 5 s are 5 executions, 327 680 field cells.
fn big_yard(dir: &std::path::Path, side: usize) -> std::path::PathBuf {
    let rows: Vec<String> = (0..side)
        .map(|y| {
            (0..side)
                .map(|x| {
                    if x == 0 || y == 0 || x == side - 1 || y == side - 1 {
                        '#'
                    } else {
                        '.'
                    }
                })
                .collect()
        })
        .collect();
    let map = serde_json::json!({"width": side, "height": side, "grid_size": 0.1, "rows": rows});
    std::fs::write(dir.join("yard.json"), map.to_string()).unwrap();
    let scenario = serde_json::json!({
        "name": "big_yard", "description": "", "lesson": "",
        "map": {"format": "json", "path": "yard.json"},
        "start": {"x": 2.0, "y": 2.0}, "goal": {"x": 60.0, "y": 60.0, "heading_deg": 90},
        "rates": {"local_path_planning": 1},
        "time_limit": 600, "expect": {"outcome": "arrived"}
    });
    let path = dir.join("big_yard.json");
    std::fs::write(&path, scenario.to_string()).unwrap();
    path
}

#[test]
fn render_waits_for_the_plan_of_a_large_map() {
    let dir = std::env::temp_dir().join(format!("rtnav-render-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    // 700 × 700 = 490 000 cells: eight executions of the full field, 8 s at 1 Hz.
    let scenario = big_yard(&dir, 700);
    let png = dir.join("yard.png");
    let out = Command::new(env!("CARGO_BIN_EXE_rtnav"))
        .args(["render", scenario.to_str().unwrap(), "--png"])
        .arg(&png)
        .args(["--root", dir.to_str().unwrap(), "--size", "200x200"])
        .output()
        .unwrap();
    let written = png.exists();
    std::fs::remove_dir_all(&dir).unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(stdout.starts_with("big_yard: planned → "), "{stdout}");
    assert!(written);
}
