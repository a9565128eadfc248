//! The IDL samples as a script sees them (spec §8, Decision 0.4 "ports and state"): a map of
//! the IDL's fields by name, `tm` included as `#{sec, nsec}`; what a script writes is
//! checked against the port's IDL type, field by field.

use rhai::{Array, Dynamic, Map};

use crate::interfaces::{ControlPoints, Direction};
use crate::rtc::{Time, TimedDouble, TimedDoubleSeq, TimedPosition, TimedVelocity};

/// A value that travels through a port a script reads or writes.
pub trait ScriptSample: Sized + Clone + 'static {
    /// The fields a script writes, in the IDL's order (`tm` first); the ones in
    /// [`ScriptSample::OPTIONAL`] may be left out.
    const FIELDS: &'static [&'static str];
    /// Fields that may be left out of a written sample (the seeds' unused `id` and `error`
    /// sequences, empty when left out).
    const OPTIONAL: &'static [&'static str] = &[];
    /// The sample as a map of its fields.
    fn to_map(&self) -> Map;
    /// The sample a script wrote, checked; the error says which field is wrong and why.
    fn from_map(map: &Map) -> Result<Self, String>;
}

fn put(map: &mut Map, key: &str, value: Dynamic) {
    map.insert(key.into(), value);
}

fn numbers(values: &[f64]) -> Dynamic {
    Dynamic::from_array(values.iter().map(|&v| Dynamic::from_float(v)).collect())
}

/// `tm` as the script sees it: `#{sec, nsec}`.
pub fn time_map(tm: Time) -> Dynamic {
    let mut m = Map::new();
    put(&mut m, "sec", Dynamic::from_int(i64::from(tm.sec)));
    put(&mut m, "nsec", Dynamic::from_int(i64::from(tm.nsec)));
    Dynamic::from_map(m)
}

/// The fields of a written map, checked for unknown names and missing required ones.
struct Fields<'a> {
    map: &'a Map,
}

impl<'a> Fields<'a> {
    fn of<T: ScriptSample>(map: &'a Map) -> Result<Self, String> {
        let idl = core::any::type_name::<T>()
            .rsplit("::")
            .next()
            .unwrap_or("sample");
        if let Some(extra) = map.keys().find(|k| !T::FIELDS.contains(&k.as_str())) {
            return Err(format!(
                "`{extra}` is not a field of {idl} (its fields: {})",
                T::FIELDS.join(", ")
            ));
        }
        if let Some(missing) = T::FIELDS
            .iter()
            .find(|f| !T::OPTIONAL.contains(f) && !map.contains_key(**f))
        {
            return Err(format!(
                "the field `{missing}` is missing (a {idl} has {})",
                T::FIELDS.join(", ")
            ));
        }
        Ok(Self { map })
    }

    fn get(&self, field: &str) -> Option<&'a Dynamic> {
        self.map.get(field)
    }

    fn number(&self, field: &str) -> Result<f64, String> {
        let v = self
            .get(field)
            .ok_or_else(|| format!("the field `{field}` is missing"))?;
        number(v)
            .ok_or_else(|| format!("the field `{field}` must be a number, not {}", what(v)))
            .and_then(|x| finite(field, x))
    }

    fn numbers(&self, field: &str) -> Result<Vec<f64>, String> {
        let Some(v) = self.get(field) else {
            return Ok(Vec::new());
        };
        let Some(array) = v.read_lock::<Array>() else {
            return Err(format!(
                "the field `{field}` must be an array of numbers, not {}",
                what(v)
            ));
        };
        array
            .iter()
            .enumerate()
            .map(|(i, x)| {
                let item = format!("{field}[{i}]");
                number(x)
                    .ok_or_else(|| format!("`{item}` must be a number, not {}", what(x)))
                    .and_then(|n| finite(&item, n))
            })
            .collect()
    }

    fn ids(&self, field: &str) -> Result<Vec<i32>, String> {
        let Some(v) = self.get(field) else {
            return Ok(Vec::new());
        };
        let Some(array) = v.read_lock::<Array>() else {
            return Err(format!(
                "the field `{field}` must be an array of whole numbers, not {}",
                what(v)
            ));
        };
        array
            .iter()
            .enumerate()
            .map(|(i, x)| {
                x.as_int()
                    .ok()
                    .and_then(|n| i32::try_from(n).ok())
                    .ok_or_else(|| {
                        format!("`{field}[{i}]` must be a whole number, not {}", what(x))
                    })
            })
            .collect()
    }

    fn tm(&self) -> Result<Time, String> {
        let v = self.get("tm").ok_or("the field `tm` is missing")?;
        let Some(m) = v.read_lock::<Map>() else {
            return Err(format!(
                "the field `tm` must be a time #{{sec, nsec}} (for example `rtc.tm`), not {}",
                what(v)
            ));
        };
        let part = |name: &str| -> Result<u32, String> {
            let x = m
                .get(name)
                .ok_or_else(|| format!("`tm.{name}` is missing (a time is #{{sec, nsec}})"))?;
            x.as_int()
                .ok()
                .and_then(|n| u32::try_from(n).ok())
                .ok_or_else(|| format!("`tm.{name}` must be a whole number ≥ 0, not {}", what(x)))
        };
        if let Some(extra) = m.keys().find(|k| !matches!(k.as_str(), "sec" | "nsec")) {
            return Err(format!("`tm.{extra}` is not a field of a time (sec, nsec)"));
        }
        let (sec, nsec) = (part("sec")?, part("nsec")?);
        if nsec >= 1_000_000_000 {
            return Err(format!("`tm.nsec` is {nsec}: it must be below 1000000000"));
        }
        Ok(Time { sec, nsec })
    }
}

/// A number a script gave: a float, or a whole number taken as one.
pub fn number(v: &Dynamic) -> Option<f64> {
    v.as_float()
        .ok()
        .or_else(|| v.as_int().ok().map(|i| i as f64))
}

fn finite(field: &str, x: f64) -> Result<f64, String> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(format!(
            "`{field}` is {x}: a sample's numbers must be finite"
        ))
    }
}

/// How a value is named to a student: "a string", "()" (nothing), "a map".
pub fn what(v: &Dynamic) -> String {
    if v.is_unit() {
        return "nothing, `()`".to_owned();
    }
    let name = v.type_name();
    let article = if name.starts_with(['a', 'e', 'i', 'o', 'u']) {
        "an"
    } else {
        "a"
    };
    let name = match name {
        "i64" => "whole number",
        "f64" => "number",
        "map" => "map",
        "array" => "array",
        "string" => "string",
        "bool" => "bool",
        "char" => "character",
        other => other,
    };
    format!("{article} {name}")
}

impl ScriptSample for TimedDoubleSeq {
    const FIELDS: &'static [&'static str] = &["tm", "data"];
    fn to_map(&self) -> Map {
        let mut m = Map::new();
        put(&mut m, "tm", time_map(self.tm));
        put(&mut m, "data", numbers(&self.data));
        m
    }
    fn from_map(map: &Map) -> Result<Self, String> {
        let f = Fields::of::<Self>(map)?;
        Ok(Self {
            tm: f.tm()?,
            data: f.numbers("data")?,
        })
    }
}

impl ScriptSample for TimedDouble {
    const FIELDS: &'static [&'static str] = &["tm", "data"];
    fn to_map(&self) -> Map {
        let mut m = Map::new();
        put(&mut m, "tm", time_map(self.tm));
        put(&mut m, "data", Dynamic::from_float(self.data));
        m
    }
    fn from_map(map: &Map) -> Result<Self, String> {
        let f = Fields::of::<Self>(map)?;
        Ok(Self {
            tm: f.tm()?,
            data: f.number("data")?,
        })
    }
}

impl ScriptSample for TimedVelocity {
    const FIELDS: &'static [&'static str] = &["tm", "id", "vx", "vy", "w", "error"];
    const OPTIONAL: &'static [&'static str] = &["id", "error"];
    fn to_map(&self) -> Map {
        let mut m = Map::new();
        put(&mut m, "tm", time_map(self.tm));
        put(
            &mut m,
            "id",
            Dynamic::from_array(
                self.id
                    .iter()
                    .map(|&i| Dynamic::from_int(i.into()))
                    .collect(),
            ),
        );
        put(&mut m, "vx", Dynamic::from_float(self.vx));
        put(&mut m, "vy", Dynamic::from_float(self.vy));
        put(&mut m, "w", Dynamic::from_float(self.w));
        put(&mut m, "error", numbers(&self.error));
        m
    }
    fn from_map(map: &Map) -> Result<Self, String> {
        let f = Fields::of::<Self>(map)?;
        Ok(Self {
            tm: f.tm()?,
            id: f.ids("id")?,
            vx: f.number("vx")?,
            vy: f.number("vy")?,
            w: f.number("w")?,
            error: f.numbers("error")?,
        })
    }
}

impl ScriptSample for TimedPosition {
    const FIELDS: &'static [&'static str] = &["tm", "id", "x", "y", "theta", "error"];
    const OPTIONAL: &'static [&'static str] = &["id", "error"];
    fn to_map(&self) -> Map {
        let mut m = Map::new();
        put(&mut m, "tm", time_map(self.tm));
        put(
            &mut m,
            "id",
            Dynamic::from_array(
                self.id
                    .iter()
                    .map(|&i| Dynamic::from_int(i.into()))
                    .collect(),
            ),
        );
        put(&mut m, "x", Dynamic::from_float(self.x));
        put(&mut m, "y", Dynamic::from_float(self.y));
        put(&mut m, "theta", Dynamic::from_float(self.theta));
        put(&mut m, "error", numbers(&self.error));
        m
    }
    fn from_map(map: &Map) -> Result<Self, String> {
        let f = Fields::of::<Self>(map)?;
        Ok(Self {
            tm: f.tm()?,
            id: f.ids("id")?,
            x: f.number("x")?,
            y: f.number("y")?,
            theta: f.number("theta")?,
            error: f.numbers("error")?,
        })
    }
}

/// Control points as a script reads them: `#{tm, points: [#{x, y}, …], direction:
/// "forward" | "backward", goal_theta}` (spec §3, 000 §5.2.4.13).
impl ScriptSample for ControlPoints {
    const FIELDS: &'static [&'static str] = &["tm", "points", "direction", "goal_theta"];
    fn to_map(&self) -> Map {
        let mut m = Map::new();
        put(&mut m, "tm", time_map(self.tm));
        let points = self
            .points
            .iter()
            .map(|&(x, y)| {
                let mut p = Map::new();
                put(&mut p, "x", Dynamic::from_float(x));
                put(&mut p, "y", Dynamic::from_float(y));
                Dynamic::from_map(p)
            })
            .collect();
        put(&mut m, "points", Dynamic::from_array(points));
        let direction = match self.direction {
            Direction::Forward => "forward",
            Direction::Backward => "backward",
        };
        put(&mut m, "direction", direction.into());
        put(&mut m, "goal_theta", Dynamic::from_float(self.goal_theta));
        m
    }
    fn from_map(map: &Map) -> Result<Self, String> {
        let f = Fields::of::<Self>(map)?;
        let tm = f.tm()?;
        let Some(v) = f.get("points") else {
            return Err("the field `points` is missing".to_owned());
        };
        let Some(array) = v.read_lock::<Array>() else {
            return Err(format!(
                "the field `points` must be an array of #{{x, y}}, not {}",
                what(v)
            ));
        };
        let mut points = Vec::with_capacity(array.len());
        for (i, p) in array.iter().enumerate() {
            let Some(p) = p.read_lock::<Map>() else {
                return Err(format!(
                    "`points[{i}]` must be a map #{{x, y}}, not {}",
                    what(p)
                ));
            };
            let xy = Fields::of::<Point>(&p)?;
            points.push((xy.number("x")?, xy.number("y")?));
        }
        let direction = match f
            .get("direction")
            .and_then(|d| d.clone().into_string().ok())
        {
            Some(d) if d == "forward" => Direction::Forward,
            Some(d) if d == "backward" => Direction::Backward,
            _ => return Err("the field `direction` must be \"forward\" or \"backward\"".to_owned()),
        };
        Ok(Self {
            tm,
            points,
            direction,
            goal_theta: f.number("goal_theta")?,
        })
    }
}

/// A control point `#{x, y}`, only to check one.
#[derive(Debug, Clone)]
struct Point;

impl ScriptSample for Point {
    const FIELDS: &'static [&'static str] = &["x", "y"];
    fn to_map(&self) -> Map {
        Map::new()
    }
    fn from_map(_: &Map) -> Result<Self, String> {
        Ok(Self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn map_of(pairs: &[(&str, Dynamic)]) -> Map {
        pairs
            .iter()
            .map(|(k, v)| ((*k).into(), v.clone()))
            .collect()
    }

    #[test]
    fn samples_go_both_ways() {
        let v = TimedVelocity {
            tm: Time { sec: 3, nsec: 500 },
            vx: 0.25,
            w: -0.5,
            ..Default::default()
        };
        assert_eq!(TimedVelocity::from_map(&v.to_map()), Ok(v));
        let s = TimedDoubleSeq {
            tm: Time { sec: 0, nsec: 1 },
            data: vec![1.0, -2.5],
        };
        assert_eq!(TimedDoubleSeq::from_map(&s.to_map()), Ok(s));
        let c = ControlPoints {
            tm: Time::default(),
            points: vec![(1.0, 2.0), (3.0, 4.0)],
            direction: Direction::Backward,
            goal_theta: 0.5,
        };
        assert_eq!(ControlPoints::from_map(&c.to_map()), Ok(c));
    }

    #[test]
    fn a_wrong_sample_names_its_field() {
        let tm = time_map(Time::default());
        let e = TimedDoubleSeq::from_map(&map_of(&[("tm", tm.clone())])).unwrap_err();
        assert!(e.contains("`data` is missing"), "{e}");
        let e = TimedDoubleSeq::from_map(&map_of(&[("tm", tm.clone()), ("data", "fast".into())]))
            .unwrap_err();
        assert!(e.contains("array of numbers, not a string"), "{e}");
        let e = TimedVelocity::from_map(&map_of(&[
            ("tm", tm.clone()),
            ("vx", Dynamic::from_float(f64::NAN)),
            ("vy", Dynamic::from_int(0)),
            ("w", Dynamic::from_int(0)),
        ]))
        .unwrap_err();
        assert!(e.contains("`vx` is NaN"), "{e}");
        let e = TimedDouble::from_map(&map_of(&[("tm", tm), ("data", 1.into()), ("x", 1.into())]))
            .unwrap_err();
        assert!(e.contains("`x` is not a field of TimedDouble"), "{e}");
        let e =
            TimedDouble::from_map(&map_of(&[("tm", 5.into()), ("data", 1.into())])).unwrap_err();
        assert!(e.contains("`tm` must be a time"), "{e}");
    }
}
