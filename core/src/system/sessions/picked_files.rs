//! [`PickedFiles`]: files a user interface hands over by name — a scenario's map files
//! (fetched from the server) or the files a person picked — and the choice of map loader
//! for picked files by their names, else by their first bytes.

use std::collections::BTreeMap;

use crate::map::GridMap;
use crate::map::formats::ros;
use crate::system::runs::scenario::{MapSource, MemoryResolver, UnknownSpec};
use crate::system::vocabulary::error::SessionError;

/// Named files in memory: paths as a scenario writes them (`fixtures/maps/…`), or the names
/// of the files a person picked.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct PickedFiles(BTreeMap<String, Vec<u8>>);

/// A picked map that cannot be loaded: the error, and the file it is about when it is one
/// file's.
#[derive(Debug, Clone, PartialEq)]
pub struct PickError {
    /// The file the error is about, if it is one file's.
    pub file: Option<String>,
    /// What is wrong.
    pub error: Box<crate::Error>,
}

impl From<SessionError> for PickError {
    fn from(e: SessionError) -> Self {
        Self {
            file: None,
            error: Box::new(e.into()),
        }
    }
}

impl std::fmt::Display for PickError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match &self.file {
            Some(name) => write!(f, "`{name}`: {}", self.error),
            None => write!(f, "{}", self.error),
        }
    }
}

fn about(name: &str, error: impl Into<crate::Error>) -> PickError {
    PickError {
        file: Some(name.to_owned()),
        error: Box::new(error.into()),
    }
}

/// Which loader a picked file is for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    Json,
    RosYaml,
    RosImage,
    MovingAi,
}

/// The loader for a file: by its extension, else by its first characters.
fn kind(name: &str, bytes: &[u8]) -> Option<Kind> {
    let lower = name.to_ascii_lowercase();
    let ext = lower.rsplit_once('.').map_or("", |(_, e)| e);
    match ext {
        "json" => return Some(Kind::Json),
        "yaml" | "yml" => return Some(Kind::RosYaml),
        "pgm" | "png" => return Some(Kind::RosImage),
        "map" => return Some(Kind::MovingAi),
        _ => {}
    }
    let head = String::from_utf8_lossy(&bytes[..bytes.len().min(64)]);
    let head = head.trim_start();
    if head.starts_with('{') {
        Some(Kind::Json)
    } else if head.starts_with("type") {
        Some(Kind::MovingAi)
    } else if head.starts_with("image") {
        Some(Kind::RosYaml)
    } else if head.starts_with("P5") || head.starts_with("P2") || bytes.starts_with(b"\x89PNG") {
        Some(Kind::RosImage)
    } else {
        None
    }
}

impl PickedFiles {
    /// No files.
    pub fn new() -> Self {
        Self::default()
    }

    /// Adds (or replaces) a file.
    pub fn add(&mut self, path: &str, bytes: Vec<u8>) {
        self.0.insert(path.to_owned(), bytes);
    }

    /// How many files there are.
    pub fn len(&self) -> usize {
        self.0.len()
    }

    /// Whether there are none.
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    /// A resolver over these files, for a scenario.
    pub fn resolver(&self) -> MemoryResolver {
        let mut r = MemoryResolver::new();
        for (path, bytes) in &self.0 {
            r.insert(path, bytes.clone());
        }
        r
    }

    /// Loads the map picked: one rtnav JSON file, one MovingAI `.map` (scaled to
    /// `movingai_grid_size` metres per cell), or a ROS YAML with the image it names — by
    /// the core's loaders ([`MapSource::load`]). Every problem is an error naming the file;
    /// nothing is loaded then. Returns the file's name and the map.
    pub fn load_map(&self, movingai_grid_size: f64) -> Result<(String, GridMap), PickError> {
        let (name, source) = self.map_source(movingai_grid_size)?;
        let map = source.load(&self.resolver()).map_err(|e| about(&name, e))?;
        Ok((name, map))
    }

    /// Which file is the map and how to read it.
    fn map_source(&self, movingai_grid_size: f64) -> Result<(String, MapSource), PickError> {
        if self.0.is_empty() {
            return Err(SessionError::NoFile.into());
        }
        let kinds: Vec<(&str, &[u8], Option<Kind>)> = self
            .0
            .iter()
            .map(|(n, b)| (n.as_str(), b.as_slice(), kind(n, b)))
            .collect();
        if let Some((name, ..)) = kinds.iter().find(|k| k.2.is_none()) {
            return Err(SessionError::UnknownFile {
                name: (*name).to_owned(),
            }
            .into());
        }
        if let Some(&(name, bytes, _)) = kinds.iter().find(|k| k.2 == Some(Kind::RosYaml)) {
            // Checked here for a clearer message than "cannot read": the image must have
            // been picked too.
            let text = std::str::from_utf8(bytes).map_err(|e| SessionError::NotText {
                name: name.to_owned(),
                reason: e.to_string(),
            })?;
            let yaml = ros::parse_yaml(text).map_err(|e| about(name, e))?;
            if !self.0.contains_key(&yaml.image) {
                return Err(SessionError::MissingImage {
                    name: name.to_owned(),
                    image: yaml.image,
                }
                .into());
            }
            return Ok((
                name.to_owned(),
                MapSource::Ros {
                    yaml: name.to_owned(),
                    unknown: UnknownSpec::default(),
                },
            ));
        }
        let [(name, _, Some(k))] = kinds.as_slice() else {
            return Err(SessionError::FileCount {
                count: self.0.len(),
            }
            .into());
        };
        let path = (*name).to_owned();
        let source = match k {
            Kind::Json => MapSource::Json { path },
            Kind::MovingAi => {
                if !(movingai_grid_size.is_finite() && movingai_grid_size > 0.0) {
                    return Err(SessionError::BadCellSize {
                        value: movingai_grid_size,
                    }
                    .into());
                }
                MapSource::Movingai {
                    path,
                    grid_size: movingai_grid_size,
                    origin: [0.0, 0.0],
                }
            }
            Kind::RosImage | Kind::RosYaml => {
                return Err(SessionError::ImageOnly {
                    name: (*name).to_owned(),
                }
                .into());
            }
        };
        Ok(((*name).to_owned(), source))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn files(list: &[(&str, &[u8])]) -> PickedFiles {
        let mut f = PickedFiles::new();
        for (n, b) in list {
            f.add(n, b.to_vec());
        }
        f
    }

    #[test]
    fn kinds_by_extension_then_content() {
        let cases: &[(&str, &[u8], Option<Kind>)] = &[
            ("a.JSON", b"", Some(Kind::Json)),
            ("a.yml", b"", Some(Kind::RosYaml)),
            ("a.pgm", b"", Some(Kind::RosImage)),
            ("arena.map", b"", Some(Kind::MovingAi)),
            ("noext", b"  {\"width\": 1}", Some(Kind::Json)),
            ("noext", b"type octile\n", Some(Kind::MovingAi)),
            ("noext", b"image: m.pgm\n", Some(Kind::RosYaml)),
            ("noext", b"hello", None),
        ];
        for &(name, bytes, expect) in cases {
            assert_eq!(kind(name, bytes), expect, "{name}");
        }
    }

    #[test]
    fn each_format_loads() {
        let json = br##"{"width": 3, "height": 2, "grid_size": 0.5, "rows": ["#..", "..."]}"##;
        let (name, map) = files(&[("m.json", json)]).load_map(1.0).unwrap();
        assert_eq!((name.as_str(), map.width(), map.height()), ("m.json", 3, 2));
        let mai = b"type octile\nheight 2\nwidth 3\nmap\n@..\n...\n";
        let (_, map) = files(&[("a.map", mai)]).load_map(0.25).unwrap();
        assert_eq!((map.width(), map.grid_size()), (3, 0.25));
        assert!(map.is_obstacle(0, 1));
        let yaml = b"image: m.pgm\nresolution: 0.1\norigin: [0, 0, 0]\nnegate: 0\n\
                     occupied_thresh: 0.65\nfree_thresh: 0.196\n";
        let pgm = b"P5 2 1 255\n\x00\xff";
        let (name, map) = files(&[("m.yaml", yaml), ("m.pgm", pgm)])
            .load_map(1.0)
            .unwrap();
        assert_eq!((name.as_str(), map.width(), map.height()), ("m.yaml", 2, 1));
        assert!(map.is_obstacle(0, 0) && !map.is_obstacle(1, 0));
    }

    #[test]
    fn bad_files_are_named_with_the_reason() {
        let ros_yaml: &[u8] = b"image: other.pgm\nresolution: 0.1\norigin: [0, 0, 0]\n\
                                negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
        let cases: Vec<(PickedFiles, &str)> = vec![
            (files(&[]), "no file chosen: expected"),
            (
                files(&[("notes.txt", b"hello")]),
                "`notes.txt` is not a map file I know",
            ),
            (files(&[("m.json", b"{\"width\": 0}")]), "`m.json`: "),
            (
                files(&[("m.pgm", b"P5 1 1 255\n\x00")]),
                "`m.pgm` is an image: a ROS map needs its .yaml",
            ),
            (
                files(&[("m.yaml", ros_yaml)]),
                "`m.yaml` names the image `other.pgm`: pick it together",
            ),
            (
                files(&[("a.json", b"{}"), ("b.json", b"{}")]),
                "2 files chosen",
            ),
            (
                files(&[("a.map", b"type octile\nheight 1\nwidth 1\nmap\n.\n")]),
                "",
            ),
        ];
        for (f, expect) in cases {
            match f.load_map(1.0) {
                Ok(_) => assert_eq!(expect, "", "loaded, expected an error"),
                Err(e) => {
                    let text = e.to_string();
                    assert!(text.starts_with(expect) && !expect.is_empty(), "{text}");
                }
            }
        }
        let movingai = files(&[("a.map", b"type octile\nheight 1\nwidth 1\nmap\n.\n")]);
        assert_eq!(
            movingai.load_map(f64::NAN).unwrap_err().to_string(),
            "MovingAI cell size NaN m must be positive"
        );
    }
}
