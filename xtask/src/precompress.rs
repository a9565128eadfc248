//! The dist folder's precompressed files: beside each file a browser gains from getting
//! compressed (the page's text, the wasm, the scenarios and their maps), `NAME.gz` (gzip at
//! its best level) and `NAME.br` (brotli at quality 11), each only when it is smaller than
//! `NAME`. A static server that knows them (nginx's `gzip_static` and `brotli_static`,
//! Caddy's `precompressed`, `cargo xtask serve`) sends one of them to a browser that accepts
//! its encoding, with `Content-Encoding` and `Vary: Accept-Encoding`; any other server sends
//! the originals, which are all still there.
//!
//! [`Encoding::negotiate`] is how `cargo xtask serve` chooses from `Accept-Encoding`.

use std::io::{Read, Write};
use std::path::{Path, PathBuf};

use crate::Result;

/// A content coding a copy is written in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Encoding {
    /// Brotli (`br`, RFC 7932): about a fifth smaller than gzip on the wasm.
    Brotli,
    /// gzip (RFC 1952): what every browser and HTTP client takes.
    Gzip,
}

impl Encoding {
    /// Every coding, in the order a server prefers them (smallest first).
    pub const ALL: [Encoding; 2] = [Encoding::Brotli, Encoding::Gzip];

    /// Its `Content-Encoding` token.
    pub fn token(self) -> &'static str {
        match self {
            Encoding::Brotli => "br",
            Encoding::Gzip => "gzip",
        }
    }

    /// The extension of its copies (`NAME.br`, `NAME.gz`).
    pub fn extension(self) -> &'static str {
        match self {
            Encoding::Brotli => "br",
            Encoding::Gzip => "gz",
        }
    }

    /// The copy of `file` in this coding (`file` with `.br` or `.gz` added).
    pub fn copy_of(self, file: &Path) -> PathBuf {
        let mut name = file.as_os_str().to_owned();
        name.push(".");
        name.push(self.extension());
        PathBuf::from(name)
    }

    /// `bytes` in this coding.
    pub fn compress(self, bytes: &[u8]) -> Vec<u8> {
        match self {
            Encoding::Brotli => brotli(bytes),
            Encoding::Gzip => gzip(bytes),
        }
    }

    /// The coding to send `file` in, for a request's `Accept-Encoding` (None: the header is
    /// absent), given which copies of it exist (`has`): the first of [`Encoding::ALL`] that the
    /// header accepts (named, or `*`, with a non-zero `q`) and that has a copy. `identity`
    /// (the file itself) is always acceptable here, so `None` means "send the original".
    pub fn negotiate(accept: Option<&str>, has: impl Fn(Encoding) -> bool) -> Option<Encoding> {
        let accept = accept?;
        // Each entry: its token (lower case) and whether its q-value is above zero.
        let entries: Vec<(String, bool)> = accept
            .split(',')
            .filter_map(|entry| {
                let mut parts = entry.split(';');
                let token = parts.next()?.trim().to_ascii_lowercase();
                if token.is_empty() {
                    return None;
                }
                let q = parts
                    .filter_map(|p| p.trim().strip_prefix("q=").or(p.trim().strip_prefix("Q=")))
                    .find_map(|q| q.trim().parse::<f64>().ok())
                    .unwrap_or(1.0);
                Some((token, q > 0.0))
            })
            .collect();
        let accepted = |token: &str| {
            entries
                .iter()
                .find(|(t, _)| t == token)
                .or_else(|| entries.iter().find(|(t, _)| t == "*"))
                .is_some_and(|&(_, ok)| ok)
        };
        Encoding::ALL
            .into_iter()
            .find(|&e| accepted(e.token()) && has(e))
    }
}

/// gzip at the best level (9).
pub fn gzip(bytes: &[u8]) -> Vec<u8> {
    let mut encoder = flate2::write::GzEncoder::new(
        Vec::with_capacity(bytes.len() / 2),
        flate2::Compression::best(),
    );
    // Writing to a Vec cannot fail.
    let _ = encoder.write_all(bytes);
    encoder.finish().unwrap_or_default()
}

/// Brotli at the best quality (11) with a 4 MiB window (`lgwin` 22).
pub fn brotli(bytes: &[u8]) -> Vec<u8> {
    let mut encoder =
        ::brotli::CompressorWriter::new(Vec::with_capacity(bytes.len() / 2), 1 << 16, 11, 22);
    // Writing to a Vec cannot fail.
    let _ = encoder.write_all(bytes);
    let _ = encoder.flush();
    encoder.into_inner()
}

/// Whether a file is worth compressing, by its extension: text, the wasm, the map formats
/// (not PNG, which is deflated already).
pub fn compressible(path: &Path) -> bool {
    matches!(
        path.extension().and_then(|e| e.to_str()).unwrap_or(""),
        "html"
            | "js"
            | "mjs"
            | "css"
            | "json"
            | "wasm"
            | "svg"
            | "txt"
            | "md"
            | "map"
            | "pgm"
            | "pnm"
            | "yaml"
            | "yml"
            | "conf"
    )
}

/// Files under this size are sent as they are: their copies would save less than a packet.
const MIN_BYTES: usize = 512;

/// What [`write_beside`] wrote: how many files got copies, their bytes and their copies'.
#[derive(Debug, Default, Clone, Copy, PartialEq, Eq)]
pub struct Written {
    /// Files with at least one copy.
    pub files: usize,
    /// Their bytes.
    pub raw: u64,
    /// Their gzip copies' bytes (the file's own where it has none).
    pub gzip: u64,
    /// Their brotli copies' bytes (the file's own where it has none).
    pub brotli: u64,
}

impl std::fmt::Display for Written {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let kb = |b: u64| b as f64 / 1000.0;
        write!(
            f,
            "{} files, {:.0} KB: {:.0} KB gzipped, {:.0} KB as brotli",
            self.files,
            kb(self.raw),
            kb(self.gzip),
            kb(self.brotli)
        )
    }
}

/// Whether `path` is a copy this module wrote: `NAME.gz` or `NAME.br` beside `NAME`.
pub fn is_copy(path: &Path) -> bool {
    let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("");
    Encoding::ALL.iter().any(|e| e.extension() == ext) && path.with_extension("").is_file()
}

/// Every file under `dir`, sorted, as paths relative to it.
pub fn files_under(dir: &Path) -> Result<Vec<PathBuf>> {
    let mut files = Vec::new();
    let mut stack = vec![PathBuf::new()];
    while let Some(rel) = stack.pop() {
        for e in std::fs::read_dir(dir.join(&rel))? {
            let e = e?;
            let rel = rel.join(e.file_name());
            if e.file_type()?.is_dir() {
                stack.push(rel);
            } else {
                files.push(rel);
            }
        }
    }
    files.sort();
    Ok(files)
}

/// `bytes` decoded from `encoding`, if they are a valid stream of it.
pub fn decode(encoding: Encoding, bytes: &[u8]) -> Option<Vec<u8>> {
    let mut out = Vec::new();
    let done = match encoding {
        Encoding::Brotli => ::brotli::Decompressor::new(bytes, 1 << 16).read_to_end(&mut out),
        Encoding::Gzip => flate2::read::GzDecoder::new(bytes).read_to_end(&mut out),
    };
    done.ok().map(|_| out)
}

/// Writes the copies of every compressible file under `dir`. A copy already there is kept if
/// it decodes to the file (a folder sealed again recompresses only what changed); any other
/// copy of a file is removed first, so none is of a file's old content.
pub fn write_beside(dir: &Path) -> Result<Written> {
    let mut written = Written::default();
    for rel in files_under(dir)? {
        let file = dir.join(&rel);
        if is_copy(&file) || !compressible(&file) {
            continue;
        }
        let bytes = std::fs::read(&file)?;
        let mut current = [None, None];
        for (i, encoding) in Encoding::ALL.into_iter().enumerate() {
            let copy = encoding.copy_of(&file);
            if let Ok(old) = std::fs::read(&copy) {
                if decode(encoding, &old).is_some_and(|d| d == bytes) {
                    current[i] = Some(old.len() as u64);
                } else {
                    std::fs::remove_file(&copy)?;
                }
            }
        }
        if bytes.len() < MIN_BYTES {
            continue;
        }
        let mut sizes = [bytes.len() as u64; 2];
        let mut any = false;
        for (i, encoding) in Encoding::ALL.into_iter().enumerate() {
            if let Some(kept) = current[i] {
                sizes[i] = kept;
                any = true;
                continue;
            }
            let copy = encoding.compress(&bytes);
            if copy.len() < bytes.len() {
                std::fs::write(encoding.copy_of(&file), &copy)
                    .map_err(|e| format!("cannot write a copy of {}: {e}", file.display()))?;
                sizes[i] = copy.len() as u64;
                any = true;
            }
        }
        if any {
            written.files += 1;
            written.raw += bytes.len() as u64;
            written.brotli += sizes[0];
            written.gzip += sizes[1];
        }
    }
    Ok(written)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn gunzip(bytes: &[u8]) -> Vec<u8> {
        decode(Encoding::Gzip, bytes).unwrap()
    }

    fn unbrotli(bytes: &[u8]) -> Vec<u8> {
        decode(Encoding::Brotli, bytes).unwrap()
    }

    #[test]
    fn copies_decode_to_the_original() {
        let text: Vec<u8> = (0..20_000u32)
            .flat_map(|i| format!("line {i} of the page\n").into_bytes())
            .collect();
        let gz = gzip(&text);
        let br = brotli(&text);
        assert_eq!(gunzip(&gz), text);
        assert_eq!(unbrotli(&br), text);
        assert!(
            br.len() < gz.len() && gz.len() < text.len() / 4,
            "{} {}",
            br.len(),
            gz.len()
        );
        // gzip's magic number and deflate method.
        assert_eq!(&gz[..3], &[0x1f, 0x8b, 8]);
    }

    #[test]
    fn negotiation_follows_accept_encoding() {
        let both = |_: Encoding| true;
        let cases: &[(Option<&str>, Option<Encoding>)] = &[
            (None, None),
            (Some(""), None),
            (Some("identity"), None),
            (Some("gzip, deflate, br, zstd"), Some(Encoding::Brotli)),
            (Some("gzip, deflate"), Some(Encoding::Gzip)),
            (Some("GZIP"), Some(Encoding::Gzip)),
            (Some("br;q=0, gzip;q=0.5"), Some(Encoding::Gzip)),
            (Some("br;q=0,gzip;q=0"), None),
            (Some("*"), Some(Encoding::Brotli)),
            (Some("*;q=0"), None),
            (Some("gzip;q=0, *"), Some(Encoding::Brotli)),
            (Some("br; q=0.000, *"), Some(Encoding::Gzip)),
        ];
        for (accept, expect) in cases {
            assert_eq!(Encoding::negotiate(*accept, both), *expect, "{accept:?}");
        }
        // Only the copies that exist.
        let only_gzip = |e: Encoding| e == Encoding::Gzip;
        assert_eq!(
            Encoding::negotiate(Some("br, gzip"), only_gzip),
            Some(Encoding::Gzip)
        );
        assert_eq!(Encoding::negotiate(Some("br"), only_gzip), None);
        assert_eq!(Encoding::negotiate(Some("br, gzip"), |_| false), None);
    }

    #[test]
    fn copies_are_written_beside_and_replaced() {
        let dir = std::env::temp_dir().join(format!("rtnav-precompress-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("js")).unwrap();
        let big = "const a = 1;\n".repeat(400);
        std::fs::write(dir.join("js/big.js"), &big).unwrap();
        std::fs::write(dir.join("small.css"), "a{}").unwrap();
        std::fs::write(dir.join("map.png"), vec![7u8; 4000]).unwrap();
        let w = write_beside(&dir).unwrap();
        assert_eq!(w.files, 1, "{w:?}");
        assert_eq!(w.raw, big.len() as u64);
        assert_eq!(
            gunzip(&std::fs::read(dir.join("js/big.js.gz")).unwrap()),
            big.as_bytes()
        );
        assert_eq!(
            unbrotli(&std::fs::read(dir.join("js/big.js.br")).unwrap()),
            big.as_bytes()
        );
        assert!(!dir.join("small.css.gz").exists() && !dir.join("map.png.gz").exists());
        assert!(is_copy(&dir.join("js/big.js.br")));
        assert!(!is_copy(&dir.join("js/big.js")));
        // Written again: the same. After a change: the copies are the new content's; a file
        // too small for copies now has none.
        assert_eq!(write_beside(&dir).unwrap(), w);
        let changed = "let b = 2;\n".repeat(500);
        std::fs::write(dir.join("js/big.js"), &changed).unwrap();
        write_beside(&dir).unwrap();
        assert_eq!(
            gunzip(&std::fs::read(dir.join("js/big.js.gz")).unwrap()),
            changed.as_bytes()
        );
        assert_eq!(
            unbrotli(&std::fs::read(dir.join("js/big.js.br")).unwrap()),
            changed.as_bytes()
        );
        std::fs::write(dir.join("js/big.js"), "let c;").unwrap();
        assert_eq!(write_beside(&dir).unwrap().files, 0);
        assert!(!dir.join("js/big.js.gz").exists() && !dir.join("js/big.js.br").exists());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
