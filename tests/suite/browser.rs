//! Headless Chromium as the oracle for the pages compgeo writes: a page must load without a
//! console error, an uncaught exception or a failed resource, and its script must work when a
//! real key event arrives.
//!
//! The harness speaks the DevTools protocol over its WebSocket (a few commands: enable the
//! runtime and log domains, navigate, evaluate, dispatch a key). It looks for `chromium`,
//! `chromium-browser` or `google-chrome` on the `PATH`, or the binary named by
//! `COMPGEO_CHROMIUM`. Without one the tests say so on stderr and pass, unless
//! `COMPGEO_REQUIRE_BROWSER` is set, as `.ci/run` sets it (after installing Debian's `chromium`):
//! there a missing browser fails.
#![cfg(feature = "cli")]

use crate::common::{run, TempDir};
use serde_json::{json, Value};
use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::os::unix::process::CommandExt;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};
use tungstenite::{Message, WebSocket};

/// How long any one wait on the browser may take before the test fails.
const PATIENCE: Duration = Duration::from_secs(60);

/// The browser binary, or `None` (with a note on stderr) where there is none and none is
/// required.
fn chromium() -> Option<PathBuf> {
    if let Some(path) = std::env::var_os("COMPGEO_CHROMIUM") {
        return Some(PathBuf::from(path));
    }
    let found = ["chromium", "chromium-browser", "google-chrome"]
        .iter()
        .find_map(|name| {
            std::env::split_paths(&std::env::var_os("PATH")?)
                .map(|dir| dir.join(name))
                .find(|p| p.is_file())
        });
    if found.is_none() {
        assert!(
            std::env::var_os("COMPGEO_REQUIRE_BROWSER").is_none(),
            "COMPGEO_REQUIRE_BROWSER is set but no chromium is on the PATH"
        );
        eprintln!(
            "browser tests skipped: no chromium, chromium-browser or google-chrome on the PATH \
             (install Debian's chromium, or set COMPGEO_CHROMIUM)"
        );
    }
    found
}

/// The browser's processes, killed as a group when dropped (Debian's `chromium` is a script
/// that starts the real binary, which starts helpers).
struct Processes(Child);

impl Drop for Processes {
    fn drop(&mut self) {
        let group = format!("-{}", self.0.id());
        let _ = Command::new("kill").args(["-9", "--", &group]).status();
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

/// One headless browser with one page, driven over the DevTools protocol.
pub struct Browser {
    _processes: Processes,
    socket: WebSocket<TcpStream>,
    next_id: u64,
    /// Every event received so far, in order.
    events: Vec<Value>,
    _profile: TempDir,
}

impl Browser {
    /// Starts the browser, or `None` where there is none (see [`chromium`]).
    pub fn start() -> Option<Browser> {
        let binary = chromium()?;
        let profile = TempDir::new("chromium");
        let child = Command::new(&binary)
            .args([
                "--headless",
                "--no-sandbox",
                "--disable-gpu",
                "--no-first-run",
                "--no-default-browser-check",
                "--remote-debugging-port=0",
                "--remote-allow-origins=*",
                "--allow-file-access-from-files",
            ])
            .arg(format!("--user-data-dir={}", profile.0.display()))
            .arg("about:blank")
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .process_group(0)
            .spawn()
            .unwrap_or_else(|e| panic!("starting {}: {e}", binary.display()));
        let mut child = Processes(child);
        // The browser names its port on stderr; keep draining stderr afterwards so it never
        // blocks on a full pipe.
        let stderr = child.0.stderr.take().unwrap();
        let (tx, rx) = std::sync::mpsc::channel();
        std::thread::spawn(move || {
            let mut tx = Some(tx);
            for line in BufReader::new(stderr).lines().map_while(Result::ok) {
                if let Some(rest) = line.split("DevTools listening on ws://").nth(1) {
                    if let Some(tx) = tx.take() {
                        let _ = tx.send(rest.split('/').next().unwrap_or("").to_string());
                    }
                }
            }
        });
        let address = rx
            .recv_timeout(PATIENCE)
            .unwrap_or_else(|_| panic!("{} never announced its DevTools port", binary.display()));
        let page_url = page_socket(&address);
        let path = page_url.split(&address).nth(1).unwrap().to_string();
        let stream = TcpStream::connect(&address).unwrap();
        stream.set_read_timeout(Some(PATIENCE)).unwrap();
        let (socket, _) = tungstenite::client(format!("ws://{address}{path}"), stream)
            .unwrap_or_else(|e| panic!("DevTools handshake: {e}"));
        let mut browser = Browser {
            _processes: child,
            socket,
            next_id: 0,
            events: Vec::new(),
            _profile: profile,
        };
        for domain in ["Runtime.enable", "Log.enable", "Page.enable"] {
            browser.call(domain, json!({}));
        }
        Some(browser)
    }

    /// Sends one command and returns its result, keeping the events that arrive meanwhile.
    pub fn call(&mut self, method: &str, params: Value) -> Value {
        self.next_id += 1;
        let id = self.next_id;
        let message = json!({"id": id, "method": method, "params": params}).to_string();
        self.socket
            .send(Message::text(message))
            .unwrap_or_else(|e| panic!("{method}: {e}"));
        loop {
            let reply = self.receive(method);
            if reply["id"].as_u64() == Some(id) {
                assert!(reply["error"].is_null(), "{method}: {}", reply["error"]);
                return reply["result"].clone();
            }
            self.events.push(reply);
        }
    }

    /// The next message from the browser.
    fn receive(&mut self, waiting_for: &str) -> Value {
        loop {
            match self.socket.read() {
                Ok(Message::Text(text)) => return serde_json::from_str(text.as_str()).unwrap(),
                Ok(_) => continue,
                Err(e) => panic!("waiting for {waiting_for}: {e}"),
            }
        }
    }

    /// Loads `file` and waits for its load event.
    pub fn open(&mut self, file: &Path) {
        let url = format!("file://{}", file.canonicalize().unwrap().display());
        let before = self.events.len();
        self.call("Page.navigate", json!({ "url": url }));
        let start = Instant::now();
        while !self.events[before..]
            .iter()
            .any(|e| e["method"] == "Page.loadEventFired")
        {
            assert!(start.elapsed() < PATIENCE, "{url} never finished loading");
            let event = self.receive("Page.loadEventFired");
            self.events.push(event);
        }
        // Let scripts that run on load finish and report.
        self.eval("new Promise(r => setTimeout(() => r(0), 50))");
    }

    /// The console errors, uncaught exceptions and failed loads seen so far.
    pub fn errors(&self) -> Vec<String> {
        self.events
            .iter()
            .filter_map(|e| {
                let p = &e["params"];
                match e["method"].as_str()? {
                    "Runtime.exceptionThrown" => Some(p["exceptionDetails"].to_string()),
                    "Runtime.consoleAPICalled"
                        if matches!(p["type"].as_str(), Some("error" | "assert")) =>
                    {
                        Some(p["args"].to_string())
                    }
                    "Log.entryAdded" if p["entry"]["level"] == "error" => {
                        Some(p["entry"].to_string())
                    }
                    _ => None,
                }
            })
            .collect()
    }

    /// The value of a JavaScript expression in the page (promises awaited).
    pub fn eval(&mut self, expression: &str) -> Value {
        let result = self.call(
            "Runtime.evaluate",
            json!({"expression": expression, "returnByValue": true, "awaitPromise": true}),
        );
        assert!(
            result["exceptionDetails"].is_null(),
            "{expression}: {}",
            result["exceptionDetails"]
        );
        result["result"]["value"].clone()
    }

    /// Presses and releases a key (a DOM key name such as `ArrowRight`), as a user would.
    pub fn press(&mut self, key: &str, code: u32) {
        for kind in ["keyDown", "keyUp"] {
            self.call(
                "Input.dispatchKeyEvent",
                json!({"type": kind, "key": key, "code": key,
                       "windowsVirtualKeyCode": code, "nativeVirtualKeyCode": code}),
            );
        }
    }
}

/// The DevTools WebSocket URL of the browser's first page, from its `/json/list`.
fn page_socket(address: &str) -> String {
    let start = Instant::now();
    loop {
        let mut stream = TcpStream::connect(address).unwrap();
        stream.set_read_timeout(Some(PATIENCE)).unwrap();
        // One write: the browser's server answers what the first packet holds.
        let request =
            format!("GET /json/list HTTP/1.1\r\nHost: {address}\r\nConnection: close\r\n\r\n");
        stream.write_all(request.as_bytes()).unwrap();
        // The server keeps the connection open: read the headers, then Content-Length bytes.
        let mut reader = BufReader::new(stream);
        let mut length = 0;
        loop {
            let mut line = String::new();
            reader.read_line(&mut line).unwrap();
            let line = line.trim_end();
            if line.is_empty() {
                break;
            }
            if let Some((name, value)) = line.split_once(':') {
                if name.eq_ignore_ascii_case("content-length") {
                    length = value.trim().parse().unwrap();
                }
            }
        }
        let mut body = vec![0; length];
        reader.read_exact(&mut body).unwrap();
        let body = String::from_utf8(body).unwrap();
        let targets: Value = serde_json::from_str(&body).unwrap_or(json!([]));
        if let Some(url) = targets.as_array().and_then(|ts| {
            ts.iter()
                .find(|t| t["type"] == "page")
                .and_then(|t| t["webSocketDebuggerUrl"].as_str())
        }) {
            return url.to_string();
        }
        assert!(start.elapsed() < PATIENCE, "no page target at {address}");
        std::thread::sleep(Duration::from_millis(50));
    }
}

#[test]
fn the_harness_sees_console_errors_exceptions_and_key_presses() {
    let Some(mut browser) = Browser::start() else {
        return;
    };
    let dir = TempDir::new("browser-harness");
    let clean = dir.path("clean.html");
    std::fs::write(
        &clean,
        "<!doctype html><title>t</title><p id=\"n\">0</p><script>\
         document.addEventListener('keydown', e => { if (e.key === 'ArrowRight') \
         document.getElementById('n').textContent = \
         String(Number(document.getElementById('n').textContent) + 1); });</script>",
    )
    .unwrap();
    browser.open(&clean);
    assert!(browser.errors().is_empty(), "{:?}", browser.errors());
    assert_eq!(
        browser.eval("document.getElementById('n').textContent"),
        "0"
    );
    browser.press("ArrowRight", 39);
    browser.press("ArrowRight", 39);
    assert_eq!(
        browser.eval("document.getElementById('n').textContent"),
        "2"
    );

    // Each kind of failure is seen: the oracle can fail.
    let broken = dir.path("broken.html");
    std::fs::write(
        &broken,
        "<!doctype html><title>t</title><img src=\"missing.svg\" alt=\"\">\
         <script>console.error('deliberate'); undefinedFunction();</script>",
    )
    .unwrap();
    browser.open(&broken);
    let errors = browser.errors().join("\n");
    assert!(errors.contains("deliberate"), "{errors}");
    assert!(errors.contains("undefinedFunction"), "{errors}");
    assert!(errors.contains("missing.svg"), "{errors}");
}

/// The `src` of every image on the page and whether it loaded with a size.
fn images(browser: &mut Browser) -> Vec<(String, bool)> {
    let found = browser.eval(
        "Array.from(document.images).map(i => [i.getAttribute('src'), i.complete && \
         i.naturalWidth > 0])",
    );
    found
        .as_array()
        .unwrap()
        .iter()
        .map(|i| (i[0].as_str().unwrap().to_string(), i[1] == true))
        .collect()
}

#[test]
fn the_report_index_its_gallery_and_a_step_page_render_without_errors() {
    let Some(mut browser) = Browser::start() else {
        return;
    };
    let dir = TempDir::new("browser-report");
    let out = dir.0.to_str().unwrap();
    let (code, _, err) = run(&["report", "--only", "hull/graham/", "--out", out], None);
    assert_eq!(code, 0, "{err}");

    browser.open(&dir.path("index.html"));
    assert!(browser.errors().is_empty(), "{:?}", browser.errors());
    let charts = images(&mut browser);
    assert!(!charts.is_empty(), "the index embeds charts");
    for (src, loaded) in &charts {
        assert!(loaded, "{src} did not load");
    }
    let rows = browser.eval("document.querySelectorAll('table tr').length");
    assert!(rows.as_u64().unwrap() >= 2, "a summary row: {rows}");
    let link = browser.eval("document.querySelector('a[href=\"gallery.html\"]') !== null");
    assert_eq!(link, true, "the index links the gallery");

    browser.open(&dir.path("gallery.html"));
    assert!(browser.errors().is_empty(), "{:?}", browser.errors());
    let pictures = images(&mut browser);
    for problem in [
        "hull",
        "diameter",
        "delaunay",
        "voronoi",
        "closest-pair",
        "emst",
        "empty-circle",
        "bezier",
        "bspline",
        "beta",
        "subdivision",
        "surface",
        "mesh",
        "colouring",
    ] {
        let src = format!("gallery/{problem}.svg");
        assert!(
            pictures.iter().any(|(s, loaded)| *s == src && *loaded),
            "{src} is shown: {pictures:?}"
        );
    }
    let pages = browser.eval(
        "Array.from(document.querySelectorAll('a')).map(a => a.getAttribute('href'))\
         .filter(h => h.endsWith('-steps.html'))",
    );
    let pages: Vec<String> = pages
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p.as_str().unwrap().to_string())
        .collect();
    assert!(pages.len() >= 5, "{pages:?}");

    // One step page from the gallery: it renders, and a key press shows the next frame.
    let page = pages.iter().find(|p| p.contains("graham")).unwrap();
    browser.open(&dir.0.join(page));
    assert!(browser.errors().is_empty(), "{:?}", browser.errors());
    let shown = "Array.from(document.querySelectorAll('section.frame')).filter(s => \
                 getComputedStyle(s).display !== 'none').map(s => Number(s.dataset.step))";
    assert_eq!(browser.eval(shown), json!([0]));
    browser.press("ArrowRight", 39);
    assert_eq!(browser.eval(shown), json!([1]));
    assert!(browser.errors().is_empty(), "{:?}", browser.errors());
}
