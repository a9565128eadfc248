//! A plain static file server (oxhttp): `cargo xtask serve` (of `web/`), the end of
//! `cargo xtask demo`, and the e2e tests' server on a free port (of the folder that holds the
//! `dist` folder, so the page is tested under a sub-path, as a static host serves it).
//!
//! It serves files only and nothing a static host does not: `GET`, a folder's `index.html`
//! (and `/rtnav` → `/rtnav/`, as static hosts redirect), no directory listings, nothing
//! outside its folder, no caching (a rebuilt wasm is picked up by a reload), and `.wasm` as
//! `application/wasm` so browsers can compile it while it streams. Where `cargo xtask dist`
//! wrote precompressed copies beside a file (`NAME.br`, `NAME.gz`: `crate::precompress`), a
//! browser that accepts their coding gets one, with `Content-Encoding`, the original's
//! `Content-Type`, and `Vary: Accept-Encoding` (as nginx's `gzip_static` does); `web/` has no
//! copies, so `cargo xtask serve` and `demo` send the files as they are.
//!
//! Why oxhttp, not tiny_http: tiny_http 0.12 hands each connection to a thread pool that can
//! queue a connection behind busy keep-alive connections when a browser opens several at once;
//! a page then waits forever for some of its modules (seen here with Chromium, on a fresh server,
//! about one load in three). oxhttp gives every connection its own thread.

use std::net::{Ipv4Addr, SocketAddr, TcpListener, TcpStream};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use oxhttp::Server;
use oxhttp::model::header::{
    ACCEPT_ENCODING, ALLOW, CACHE_CONTROL, CONTENT_ENCODING, CONTENT_TYPE, LOCATION, VARY,
};
use oxhttp::model::{Body, Method, Request, Response, StatusCode};

use crate::Result;
use crate::precompress::{self, Encoding};
use crate::tools;

/// The directory served.
pub fn web_root() -> PathBuf {
    tools::repo_root().join("web")
}

/// Serves `root` on `127.0.0.1:port` until the process is stopped.
pub fn serve_forever(root: PathBuf, port: u16) -> Result {
    let address = SocketAddr::from((Ipv4Addr::LOCALHOST, port));
    let shown = root.clone();
    let server = Server::new(move |request| respond(&root, request))
        .bind(address)
        .with_global_timeout(Duration::from_secs(60))
        .with_max_concurrent_connections(64)
        .spawn()
        .map_err(|e| {
            format!(
                "cannot listen on {address}: {e} (is another server running? \
                 try `cargo xtask serve --port N`)"
            )
        })?;
    println!(
        "\nrtnav demo: http://{address}/  (serving {}; Ctrl-C to stop)\n",
        shown.display()
    );
    server.join()?;
    Ok(())
}

/// `cargo xtask serve --dir DIR` on a free port, as a child process (so it can be stopped),
/// for the e2e tests. Dropping it stops the server.
#[derive(Debug)]
pub struct Background {
    child: Child,
    /// `http://127.0.0.1:PORT/`.
    pub url: String,
}

impl Background {
    /// Starts serving `dir` on a port the OS picks and waits until it accepts connections.
    pub fn start(dir: &Path) -> Result<Self> {
        let port = TcpListener::bind((Ipv4Addr::LOCALHOST, 0))?
            .local_addr()?
            .port();
        let child = Command::new(std::env::current_exe()?)
            .args(["serve", "--port", &port.to_string(), "--dir"])
            .arg(dir)
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .spawn()?;
        let mut server = Self {
            child,
            url: format!("http://127.0.0.1:{port}/"),
        };
        let deadline = Instant::now() + Duration::from_secs(20);
        while TcpStream::connect((Ipv4Addr::LOCALHOST, port)).is_err() {
            if let Some(status) = server.child.try_wait()? {
                return Err(format!("the server exited at start-up ({status})").into());
            }
            if Instant::now() > deadline {
                return Err(format!("the server did not start listening on port {port}").into());
            }
            std::thread::sleep(Duration::from_millis(50));
        }
        Ok(server)
    }
}

impl Drop for Background {
    /// Stops the server.
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// The file for a request's URL path, if it names one under `root`: `/` and directories mean
/// their `index.html`; `..`, hidden names and anything odd are refused.
fn resolve(root: &Path, path: &str) -> Option<PathBuf> {
    let mut file = root.to_path_buf();
    for segment in path.split('/').filter(|s| !s.is_empty()) {
        let plain = segment
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || matches!(c, '-' | '_' | '.'));
        if !plain || segment.starts_with('.') {
            return None;
        }
        file.push(segment);
    }
    if file.is_dir() {
        file.push("index.html");
    }
    file.is_file().then_some(file)
}

/// The `Content-Type` for a file name.
fn content_type(path: &Path) -> &'static str {
    match path.extension().and_then(|e| e.to_str()).unwrap_or("") {
        "html" => "text/html; charset=utf-8",
        "js" | "mjs" => "text/javascript; charset=utf-8",
        "wasm" => "application/wasm",
        "css" => "text/css; charset=utf-8",
        "json" | "map" => "application/json",
        "png" => "image/png",
        "svg" => "image/svg+xml",
        "ico" => "image/x-icon",
        "txt" | "md" | "conf" | "ts" | "yaml" | "yml" => "text/plain; charset=utf-8",
        "pgm" => "image/x-portable-graymap",
        "gz" => "application/gzip",
        "br" => "application/x-brotli",
        _ => "application/octet-stream",
    }
}

fn status(code: StatusCode, text: &'static str) -> Response<Body> {
    let mut response = Response::new(Body::from(text));
    *response.status_mut() = code;
    response
}

/// The answer to `request`: GET, and HEAD (the same status and headers, no body; a link
/// checker's or a cache's question), of a file under `root`; any other method is 405.
fn respond(root: &Path, request: &mut Request<Body>) -> Response<Body> {
    let head = request.method() == Method::HEAD;
    let mut response = answer(root, request);
    if head {
        *response.body_mut() = Body::empty();
    }
    response
}

fn answer(root: &Path, request: &mut Request<Body>) -> Response<Body> {
    let path = request.uri().path();
    if request.method() != Method::GET && request.method() != Method::HEAD {
        eprintln!("serve: 405 {} {path}", request.method());
        let mut response = status(StatusCode::METHOD_NOT_ALLOWED, "only GET and HEAD");
        response
            .headers_mut()
            .insert(ALLOW, oxhttp::model::HeaderValue::from_static("GET, HEAD"));
        return response;
    }
    // A folder without its slash: relative URLs in its page need it.
    if !path.ends_with('/')
        && resolve(root, path).is_some_and(|_| root.join(path.trim_start_matches('/')).is_dir())
    {
        return Response::builder()
            .status(StatusCode::MOVED_PERMANENTLY)
            .header(LOCATION, format!("{path}/"))
            .body(Body::empty())
            .unwrap_or_else(|_| status(StatusCode::INTERNAL_SERVER_ERROR, "bad header"));
    }
    let Some(file) = resolve(root, path) else {
        eprintln!("serve: 404 GET {path}");
        return status(StatusCode::NOT_FOUND, "not found");
    };
    let accept = request
        .headers()
        .get(ACCEPT_ENCODING)
        .and_then(|v| v.to_str().ok());
    let compressible = precompress::compressible(&file);
    let encoding = compressible
        .then(|| Encoding::negotiate(accept, |e| e.copy_of(&file).is_file()))
        .flatten();
    let sent = encoding.map_or_else(|| file.clone(), |e| e.copy_of(&file));
    match std::fs::read(&sent) {
        Ok(bytes) => {
            let mut response = Response::builder()
                .header(CONTENT_TYPE, content_type(&file))
                .header(CACHE_CONTROL, "no-store");
            if compressible {
                response = response.header(VARY, "Accept-Encoding");
            }
            if let Some(e) = encoding {
                response = response.header(CONTENT_ENCODING, e.token());
            }
            response
                .body(Body::from(bytes))
                .unwrap_or_else(|_| status(StatusCode::INTERNAL_SERVER_ERROR, "bad header"))
        }
        Err(e) => {
            eprintln!("serve: 500 GET {path}: {e}");
            status(StatusCode::INTERNAL_SERVER_ERROR, "cannot read the file")
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn resolves_only_plain_paths_under_the_root() {
        let root = web_root();
        let cases: &[(&str, Option<&str>)] = &[
            ("/", Some("index.html")),
            ("/index.html", Some("index.html")),
            ("/js/loop.js", Some("js/loop.js")),
            ("/../Cargo.toml", None),
            ("/%2e%2e/Cargo.toml", None),
            ("/.hidden", None),
            ("/no-such-file.js", None),
        ];
        for (url, expect) in cases {
            assert_eq!(resolve(&root, url), expect.map(|f| root.join(f)), "{url}");
        }
    }

    /// `GET path` with `Accept-Encoding: accept` (none if None) from `root`: the status, the
    /// `Content-Type`, `Content-Encoding` and `Vary` headers, and the body.
    fn get(root: &Path, path: &str, accept: Option<&str>) -> (u16, [Option<String>; 3], Vec<u8>) {
        let mut request = Request::builder().uri(path);
        if let Some(a) = accept {
            request = request.header(ACCEPT_ENCODING, a);
        }
        let mut request = request.body(Body::empty()).unwrap();
        let response = respond(root, &mut request);
        let header = |name| {
            response
                .headers()
                .get(name)
                .map(|v: &oxhttp::model::HeaderValue| v.to_str().unwrap().to_owned())
        };
        let headers = [header(CONTENT_TYPE), header(CONTENT_ENCODING), header(VARY)];
        (
            response.status().as_u16(),
            headers,
            response.into_body().to_vec().unwrap(),
        )
    }

    #[test]
    fn precompressed_copies_are_sent_to_browsers_that_accept_them() {
        let root = std::env::temp_dir().join(format!("rtnav-serve-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&root);
        std::fs::create_dir_all(root.join("pkg")).unwrap();
        let module: Vec<u8> = (0..50_000u32)
            .flat_map(|i| (i % 251).to_le_bytes())
            .collect();
        std::fs::write(root.join("pkg/m.wasm"), &module).unwrap();
        std::fs::write(root.join("map.png"), vec![1u8; 2000]).unwrap();
        precompress::write_beside(&root).unwrap();
        let (gz, br) = (
            std::fs::read(root.join("pkg/m.wasm.gz")).unwrap(),
            std::fs::read(root.join("pkg/m.wasm.br")).unwrap(),
        );
        let wasm = Some("application/wasm".to_owned());
        let vary = Some("Accept-Encoding".to_owned());
        let cases = [
            (Some("gzip, deflate, br, zstd"), Some("br"), &br),
            (Some("gzip, deflate"), Some("gzip"), &gz),
            (Some("br;q=0, gzip"), Some("gzip"), &gz),
            (Some("identity"), None, &module),
            (None, None, &module),
        ];
        for (accept, coding, body) in cases {
            let (code, headers, got) = get(&root, "/pkg/m.wasm", accept);
            assert_eq!(code, 200, "{accept:?}");
            assert_eq!(
                headers,
                [wasm.clone(), coding.map(str::to_owned), vary.clone()],
                "{accept:?}"
            );
            assert!(got == *body, "{accept:?}: the wrong body");
        }
        // Not compressible: no copies, no Vary.
        let (code, headers, _) = get(&root, "/map.png", Some("br, gzip"));
        assert_eq!(code, 200);
        assert_eq!(headers, [Some("image/png".to_owned()), None, None]);
        // A copy asked for by its own name is a plain file.
        let (_, headers, got) = get(&root, "/pkg/m.wasm.gz", Some("br, gzip"));
        assert_eq!(headers[0].as_deref(), Some("application/gzip"));
        assert_eq!(headers[1], None);
        assert!(got == gz);
        std::fs::remove_dir_all(&root).unwrap();
    }

    #[test]
    fn head_is_answered_as_get_without_the_body() {
        let root = web_root();
        let (code, headers, body) = get(&root, "/index.html", None);
        assert_eq!(code, 200);
        for method in [Method::HEAD, Method::POST] {
            let mut request = Request::builder()
                .method(method.clone())
                .uri("/index.html")
                .body(Body::empty())
                .unwrap();
            let response = respond(&root, &mut request);
            let content_type = response
                .headers()
                .get(CONTENT_TYPE)
                .map(|v| v.to_str().unwrap().to_owned());
            if method == Method::HEAD {
                assert_eq!(response.status().as_u16(), 200);
                assert_eq!(content_type, headers[0]);
                assert!(response.into_body().to_vec().unwrap().is_empty());
            } else {
                assert_eq!(response.status().as_u16(), 405);
                assert_eq!(response.headers().get(ALLOW).unwrap(), "GET, HEAD");
            }
        }
        assert!(!body.is_empty());
    }

    #[test]
    fn wasm_and_js_have_their_mime_types() {
        let cases = [
            ("a.wasm", "application/wasm"),
            ("pkg/rtnav_wasm.js", "text/javascript; charset=utf-8"),
            ("index.html", "text/html; charset=utf-8"),
            ("x.bin", "application/octet-stream"),
        ];
        for (file, expect) in cases {
            assert_eq!(content_type(Path::new(file)), expect, "{file}");
        }
    }
}
