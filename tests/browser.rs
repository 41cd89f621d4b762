//! The report page in a real browser: headless Chromium (Debian's `chromium`, which
//! `.ci/run` installs) loads `figures/index.html` from disk, every image must load and no
//! console error or failed load may be logged; a screenshot of the first screen and one of
//! the whole page are written under the target folder (`target/tmp/`). `REPRO_REPORT_PAGE`
//! names another page (a preview folder's). Without Chromium the test fails under CI
//! (`CI=true`) and is skipped, loudly, elsewhere.
//!
//! Chromium is driven by the DevTools protocol over `--remote-debugging-pipe` (JSON messages
//! ended by a NUL byte on the child's file descriptors 3 and 4): no WebSocket client, no
//! browser download.

use serde_json::{json, Value};
use std::io::{BufRead, BufReader, Write};
use std::os::fd::AsRawFd;
use std::os::unix::process::CommandExt;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::sync::mpsc::{channel, Receiver};
use std::time::{Duration, Instant};

/// How long one protocol answer may take: loading the page with its fifteen SVGs takes well
/// under a second here; a minute allows for a loaded CI machine without hanging the suite.
const ANSWER_TIMEOUT: Duration = Duration::from_secs(60);

/// Width of the screenshots, CSS pixels: wider than the page's 60em column.
const WIDTH: u32 = 1200;

/// The browser, its end of the pipes and what it has said.
struct Browser {
    child: Child,
    to: std::io::PipeWriter,
    from: Receiver<Value>,
    next_id: u64,
    /// Events received while waiting for answers, in order.
    events: Vec<Value>,
}

impl Browser {
    fn launch(binary: &Path, profile: &Path) -> Browser {
        let (child_reads, to) = std::io::pipe().expect("a pipe");
        let (from_child, child_writes) = std::io::pipe().expect("a pipe");
        let (r, w) = (child_reads.as_raw_fd(), child_writes.as_raw_fd());
        let mut cmd = Command::new(binary);
        cmd.args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--hide-scrollbars",
            "--no-first-run",
            "--remote-debugging-pipe",
            &format!("--window-size={WIDTH},1000"),
            &format!("--user-data-dir={}", profile.display()),
            "about:blank",
        ])
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::null());
        // SAFETY: between fork and exec only async-signal-safe calls (fcntl, dup2) on
        // descriptors open in the parent. Both ends are first copied above 10, so that
        // neither is overwritten by the other's dup2 when one of them is 3 or 4, and so that
        // dup2 always makes a copy without close-on-exec.
        unsafe {
            cmd.pre_exec(move || {
                let (r, w) = (
                    libc::fcntl(r, libc::F_DUPFD, 10),
                    libc::fcntl(w, libc::F_DUPFD, 10),
                );
                if r < 0 || w < 0 || libc::dup2(r, 3) < 0 || libc::dup2(w, 4) < 0 {
                    return Err(std::io::Error::last_os_error());
                }
                Ok(())
            });
        }
        let child = cmd.spawn().expect("chromium starts");
        drop((child_reads, child_writes));
        let (tx, rx) = channel();
        std::thread::spawn(move || {
            let mut reader = BufReader::new(from_child);
            let mut buf = Vec::new();
            while reader.read_until(0, &mut buf).is_ok_and(|n| n > 0) {
                buf.pop_if(|b| *b == 0);
                if let Ok(v) = serde_json::from_slice::<Value>(&buf) {
                    if tx.send(v).is_err() {
                        break;
                    }
                }
                buf.clear();
            }
        });
        Browser {
            child,
            to,
            from: rx,
            next_id: 0,
            events: Vec::new(),
        }
    }

    /// Sends a command (to a page's session if given) and waits for its answer.
    fn call(&mut self, session: Option<&str>, method: &str, params: Value) -> Value {
        self.next_id += 1;
        let id = self.next_id;
        let mut msg = json!({ "id": id, "method": method, "params": params });
        if let Some(s) = session {
            msg["sessionId"] = json!(s);
        }
        let mut bytes = serde_json::to_vec(&msg).unwrap();
        bytes.push(0);
        self.to.write_all(&bytes).expect("chromium reads its pipe");
        let answer = self.receive(&format!("an answer to {method}"), |m| m["id"] == json!(id));
        assert!(answer.get("error").is_none(), "{method} failed: {answer}");
        answer["result"].clone()
    }

    /// Receives messages, keeping the events, until one is `wanted`, which it returns.
    fn receive(&mut self, what: &str, wanted: impl Fn(&Value) -> bool) -> Value {
        let deadline = Instant::now() + ANSWER_TIMEOUT;
        loop {
            let left = deadline.saturating_duration_since(Instant::now());
            let m = self
                .from
                .recv_timeout(left)
                .unwrap_or_else(|e| panic!("no {what} from chromium: {e}"));
            if wanted(&m) {
                return m;
            }
            self.events.push(m);
        }
    }

    /// The value of a JavaScript expression in the page, through JSON.
    fn evaluate(&mut self, session: Option<&str>, expression: &str) -> Value {
        let r = self.call(
            session,
            "Runtime.evaluate",
            json!({ "expression": format!("JSON.stringify({expression})"), "returnByValue": true }),
        );
        serde_json::from_str(r["result"]["value"].as_str().unwrap_or("null"))
            .unwrap_or_else(|e| panic!("{expression}: {e}: {r}"))
    }

    /// Waits for the event `method`, keeping every event.
    fn wait_for(&mut self, method: &str) {
        if !self.events.iter().any(|e| e["method"] == method) {
            let event = self.receive(method, |m| m["method"] == method);
            self.events.push(event);
        }
    }
}

impl Drop for Browser {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// Standard base64 (the screenshots' encoding in the protocol).
fn base64_decode(text: &str) -> Vec<u8> {
    let value = |c: u8| match c {
        b'A'..=b'Z' => c - b'A',
        b'a'..=b'z' => c - b'a' + 26,
        b'0'..=b'9' => c - b'0' + 52,
        b'+' => 62,
        _ => 63,
    };
    let digits: Vec<u8> = text.bytes().filter(|&c| c != b'=').map(value).collect();
    digits
        .chunks(4)
        .flat_map(|q| {
            let n = q
                .iter()
                .enumerate()
                .fold(0u32, |n, (i, &d)| n | u32::from(d) << (18 - 6 * i));
            let bytes = [(n >> 16) as u8, (n >> 8) as u8, n as u8];
            bytes.into_iter().take(q.len().saturating_sub(1))
        })
        .collect()
}

/// Chromium on this machine, if any.
fn chromium() -> Option<PathBuf> {
    ["chromium", "chromium-browser", "google-chrome"]
        .iter()
        .find_map(|name| {
            let out = Command::new("which").arg(name).output().ok()?;
            out.status
                .success()
                .then(|| PathBuf::from(String::from_utf8_lossy(&out.stdout).trim()))
        })
}

/// The messages of the events that report a problem: console errors, uncaught exceptions,
/// error log entries (a resource that failed to load is one).
fn problems(events: &[Value]) -> Vec<String> {
    events
        .iter()
        .filter_map(|e| match e["method"].as_str()? {
            "Runtime.exceptionThrown" => Some(e["params"]["exceptionDetails"].to_string()),
            "Runtime.consoleAPICalled" if e["params"]["type"] == "error" => {
                Some(e["params"]["args"].to_string())
            }
            "Log.entryAdded" if e["params"]["entry"]["level"] == "error" => Some(format!(
                "{} {}",
                e["params"]["entry"]["text"], e["params"]["entry"]["url"]
            )),
            _ => None,
        })
        .collect()
}

#[test]
fn the_report_page_loads_in_chromium_with_every_image_and_no_error() {
    let page = std::env::var_os("REPRO_REPORT_PAGE")
        .map(PathBuf::from)
        .unwrap_or_else(|| Path::new(env!("CARGO_MANIFEST_DIR")).join("figures/index.html"));
    let page = page
        .canonicalize()
        .unwrap_or_else(|e| panic!("{}: {e}", page.display()));
    let Some(binary) = chromium() else {
        let ci = std::env::var("CI").is_ok_and(|v| v == "true");
        assert!(
            !ci,
            "chromium is missing: .ci/run installs Debian's package `chromium`"
        );
        eprintln!(
            "\n*** SKIPPED: the report's browser test needs chromium \
             (apt-get install chromium); under CI=true it fails instead ***\n"
        );
        return;
    };
    let out = PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    let profile = tempfile_dir(&out);
    let mut b = Browser::launch(&binary, &profile);
    let targets = b.call(None, "Target.getTargets", json!({}));
    let target = targets["targetInfos"]
        .as_array()
        .and_then(|t| t.iter().find(|t| t["type"] == "page"))
        .map(|t| t["targetId"].clone())
        .expect("chromium opens a page");
    let attached = b.call(
        None,
        "Target.attachToTarget",
        json!({ "targetId": target, "flatten": true }),
    );
    let session = attached["sessionId"]
        .as_str()
        .expect("a session")
        .to_string();
    let s = Some(session.as_str());
    for domain in ["Page.enable", "Runtime.enable", "Log.enable"] {
        b.call(s, domain, json!({}));
    }
    let url = format!("file://{}", page.display());
    b.call(s, "Page.navigate", json!({ "url": url }));
    b.wait_for("Page.loadEventFired");
    let images = b.evaluate(
        s,
        "[document.images.length, Array.from(document.images)\
         .filter(i => !(i.complete && i.naturalWidth > 0)).map(i => i.src)]",
    );
    let metrics = b.call(s, "Page.getLayoutMetrics", json!({}));
    let height = metrics["cssContentSize"]["height"]
        .as_f64()
        .unwrap_or(1000.0);
    // The first screen, the whole page, and one picture per section, to look at a part of
    // the page at full size.
    let sections = b.evaluate(
        s,
        "Array.from(document.querySelectorAll('section[id]')).map(e => { \
         const r = e.getBoundingClientRect(); return [e.id, r.top + window.scrollY, r.height]; })",
    );
    let sections: Vec<(String, f64, f64)> =
        serde_json::from_value(sections).expect("the page's sections as JSON");
    let whole = [
        ("first-screen".to_string(), 0.0, 1000.0),
        ("page".to_string(), 0.0, height),
    ];
    for (name, y, h) in whole.into_iter().chain(sections) {
        let shot = b.call(
            s,
            "Page.captureScreenshot",
            json!({
                "format": "png",
                "captureBeyondViewport": true,
                "clip": { "x": 0, "y": y, "width": WIDTH, "height": h, "scale": 1 }
            }),
        );
        let png = base64_decode(shot["data"].as_str().expect("a screenshot"));
        assert!(png.starts_with(b"\x89PNG"), "a PNG");
        let file = if name.contains("screen") || name == "page" {
            format!("report-{name}.png")
        } else {
            format!("report-section-{name}.png")
        };
        std::fs::write(out.join(file), png).expect("the screenshot is written");
    }
    eprintln!(
        "report screenshots: {}, {} and report-section-*.png beside them",
        out.join("report-first-screen.png").display(),
        out.join("report-page.png").display()
    );
    let problems = problems(&b.events);
    drop(b);
    let _ = std::fs::remove_dir_all(&profile);
    assert!(
        images[0].as_u64().unwrap_or(0) > 0,
        "{}: the page shows no image",
        page.display()
    );
    assert_eq!(images[1], json!([]), "images that did not load");
    assert!(problems.is_empty(), "console errors: {problems:#?}");
}

/// A fresh profile folder for Chromium under `dir`.
fn tempfile_dir(dir: &Path) -> PathBuf {
    let p = dir.join(format!("chromium-profile-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&p);
    std::fs::create_dir_all(&p).expect("a profile folder");
    p
}

#[test]
fn base64_decodes() {
    assert_eq!(base64_decode("aGVsbG8="), b"hello");
    assert_eq!(base64_decode("aGk="), b"hi");
    assert_eq!(base64_decode("YWJj"), b"abc");
}
