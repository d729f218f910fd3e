//! What window.rs needs to run the built program in a real X server and look at it: a
//! private Xvfb, the program on it, xdotool for the keys, and x11rb for screenshots, the window's
//! title, size hints and size, windows of the test's own, a window manager's close request, and
//! X's DAMAGE extension to count the frames the program sends. Everything the test starts is
//! killed when its `Session` is dropped, also when the test fails.
use std::io::{BufRead, BufReader};
use std::process::{Child, Command, ExitStatus, Stdio};
use std::sync::{Mutex, MutexGuard, mpsc};
use std::thread::sleep;
use std::time::{Duration, Instant};
use x11rb::connection::Connection;
use x11rb::cookie::{Cookie, VoidCookie};
use x11rb::errors::{ConnectionError, ReplyError};
use x11rb::properties::WmSizeHints;
use x11rb::protocol::Event;
use x11rb::protocol::damage::{ConnectionExt as _, ReportLevel};
use x11rb::protocol::xproto::{
    AtomEnum, ClientMessageEvent, ConfigureWindowAux, ConnectionExt as _, CreateWindowAux,
    EventMask, ImageFormat, WindowClass,
};
use x11rb::rust_connection::RustConnection;
use x11rb::x11_utils::TryParse;

/// What a user installs for these tests on Debian or Ubuntu.
pub const INSTALL: &str = "apt-get install xvfb xdotool";

/// One test at a time: the distances and the CPU figures are timings, which other tests' Xvfbs
/// and programs rendering on the same cores would disturb.
static ONE_AT_A_TIME: Mutex<()> = Mutex::new(());

/// How often a wait looks again.
const POLL: Duration = Duration::from_millis(50);

/// The pixels of a window, 0RGB as the program's frame, row after row.
pub struct Image {
    pub width: usize,
    pub height: usize,
    pub pixels: Vec<u32>,
}

impl Image {
    pub fn at(&self, x: usize, y: usize) -> u32 {
        self.pixels[y * self.width + x]
    }
}

/// Calls `check` every 50 ms until it gives Some, for at most `timeout`: its last answer.
pub fn wait_until<T>(timeout: Duration, mut check: impl FnMut() -> Option<T>) -> Option<T> {
    let deadline = Instant::now() + timeout;
    loop {
        if let Some(found) = check() {
            return Some(found);
        }
        if Instant::now() >= deadline {
            return None;
        }
        sleep(POLL);
    }
}

/// A child process killed (and reaped) when dropped.
struct Killed(Child);

impl Drop for Killed {
    fn drop(&mut self) {
        let _ = self.0.kill();
        let _ = self.0.wait();
    }
}

/// The program in its own Xvfb, its window found, mapped and given the focus.
pub struct Session {
    program: Killed, // dropped first: the program, then its X server
    xvfb: Killed,
    x: RustConnection,
    root: u32,
    display: String,
    pub window: u32,
    _one_at_a_time: MutexGuard<'static, ()>,
}

impl Session {
    /// Starts Xvfb on a free display (1280x1024, 24 bits), the built program on it (built first,
    /// see built.rs), and waits until the program's window is on the screen with the focus.
    pub fn start() -> Session {
        let raytracer = &crate::built::built().raytracer;
        let lock = ONE_AT_A_TIME
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner());
        let mut xvfb = Command::new("Xvfb")
            .args([
                "-displayfd",
                "1",
                "-screen",
                "0",
                "1280x1024x24",
                "-nolisten",
                "tcp",
            ])
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .unwrap_or_else(|error| panic!("{}", missing("Xvfb", error)));
        let stdout = xvfb.stdout.take().expect("Xvfb's stdout");
        let xvfb = Killed(xvfb);
        let display = read_line_within(stdout, Duration::from_secs(20))
            .map(|number| format!(":{}", number.trim()))
            .filter(|display| display.len() > 1)
            .expect("Xvfb gave no display number within 20 s: it did not start, or not in time");
        let (x, screen) = x11rb::connect(Some(&display)).unwrap_or_else(|error| {
            panic!("the test could not connect to Xvfb at {display}: {error}")
        });
        let root = x.setup().roots[screen].root;
        let program = Command::new(raytracer)
            .env("DISPLAY", &display)
            .env_remove("WAYLAND_DISPLAY")
            .spawn()
            .expect("the test could not start the built program");
        let mut session = Session {
            program: Killed(program),
            xvfb,
            x,
            root,
            display,
            window: 0,
            _one_at_a_time: lock,
        };
        let found = session.xdotool_within(
            &["search", "--sync", "--onlyvisible", "--name", "raytracer"],
            Duration::from_secs(20),
        );
        session.window = found
            .lines()
            .next()
            .and_then(|id| id.trim().parse().ok())
            .unwrap_or_else(|| panic!("xdotool found no raytracer window; it said: {found}"));
        session.focus(session.window);
        session
    }

    /// Runs xdotool on the session's display, for at most 10 s; what it printed.
    pub fn xdotool(&self, args: &[&str]) -> String {
        self.xdotool_within(args, Duration::from_secs(10))
    }

    fn xdotool_within(&self, args: &[&str], timeout: Duration) -> String {
        let child = Command::new("xdotool")
            .args(args)
            .env("DISPLAY", &self.display)
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap_or_else(|error| panic!("{}", missing("xdotool", error)));
        let mut child = Killed(child);
        let status = wait_until(timeout, || child.0.try_wait().expect("xdotool's status"))
            .unwrap_or_else(|| {
                panic!(
                    "xdotool {} did not finish within {timeout:?}",
                    args.join(" ")
                )
            });
        let mut output = String::new();
        for stream in [
            child.0.stdout.take().map(read_all),
            child.0.stderr.take().map(read_all),
        ] {
            output += &stream.unwrap_or_default();
        }
        assert!(
            status.success(),
            "xdotool {} failed ({status}): {output}",
            args.join(" ")
        );
        output
    }

    /// Gives a window the keyboard focus, as clicking on it would, and waits until it has it.
    pub fn focus(&self, window: u32) {
        self.xdotool(&["windowfocus", "--sync", &window.to_string()]);
    }

    pub fn key_down(&self, key: &str) {
        self.xdotool(&["keydown", key]);
    }

    pub fn key_up(&self, key: &str) {
        self.xdotool(&["keyup", key]);
    }

    /// Presses a key and lets it go a tenth of a second later, as a finger does. (minifb reads
    /// which keys are down once a step: a press and release in the same 1/60 s would be missed.)
    pub fn press(&self, key: &str) {
        self.key_down(key);
        sleep(Duration::from_millis(100));
        self.key_up(key);
    }

    /// What the screen shows where the program's window is: what a user sees of it.
    pub fn screenshot(&self) -> Image {
        let ((x, y), (width, height)) = (self.position(), self.size());
        let image = self
            .x
            .get_image(ImageFormat::Z_PIXMAP, self.root, x, y, width, height, !0);
        let image = answer(
            image,
            "screenshot of the screen where the program's window is",
        );
        assert!(
            image.depth == 24,
            "Xvfb should run at depth 24, not {}",
            image.depth
        );
        let pixels = image
            .data
            .chunks_exact(4) // 32 bits a pixel, blue first
            .map(|bytes| u32::from_le_bytes(bytes.try_into().unwrap()) & 0xff_ffff)
            .collect();
        Image {
            width: width.into(),
            height: height.into(),
            pixels,
        }
    }

    /// The program's window's width and height.
    pub fn size(&self) -> (u16, u16) {
        let geometry = answer(self.x.get_geometry(self.window), "geometry of the window");
        (geometry.width, geometry.height)
    }

    /// The program's window's title (WM_NAME), as a window manager shows it above the window.
    pub fn title(&self) -> String {
        let (name, any) = (AtomEnum::WM_NAME, AtomEnum::ANY);
        let title = self.x.get_property(false, self.window, name, any, 0, 1024);
        String::from_utf8_lossy(&answer(title, "title of the window").value).into_owned()
    }

    /// The size the window's WM_NORMAL_HINTS fix it at (their least and greatest size the same),
    /// which a window manager then keeps; None if they leave it free. Xvfb has no window manager.
    pub fn fixed_size(&self) -> Option<(i32, i32)> {
        let hints = WmSizeHints::get_normal_hints(&self.x, self.window)
            .map_err(ReplyError::from)
            .and_then(|cookie| cookie.reply())
            .unwrap_or_else(|error| panic!("Xvfb gave no WM_NORMAL_HINTS of the window: {error}"));
        let hints = hints?;
        hints.max_size.filter(|&most| hints.min_size == Some(most))
    }

    /// Starts counting the frames the program puts in its window, from outside: X's DAMAGE
    /// extension reports each drawing into the window, and the program draws only by sending a
    /// frame (minifb's one XPutImage of the whole window).
    pub fn watch_updates(&self) -> Updates<'_> {
        let version = self.x.damage_query_version(1, 1);
        answer(version, "version of its DAMAGE extension");
        let id = self.x.generate_id().expect("an X id for the DAMAGE object");
        let create = self
            .x
            .damage_create(id, self.window, ReportLevel::RAW_RECTANGLES);
        checked(create, "watch the program's window with DAMAGE");
        let updates = Updates {
            x: &self.x,
            damage: id,
        };
        updates.take(); // DAMAGE's first report, the whole window, is no frame
        updates
    }

    /// The program's window's top left corner on the screen.
    pub fn position(&self) -> (i16, i16) {
        let geometry = answer(self.x.get_geometry(self.window), "geometry of the window");
        (geometry.x, geometry.y)
    }

    /// Makes the program's window `width` x `height`, as a window manager does when the user
    /// drags its edge, and waits until the X server has (the window is then black: X keeps
    /// nothing of a resized window's pixels).
    pub fn resize(&self, width: u16, height: u16) {
        let size = ConfigureWindowAux::new()
            .width(u32::from(width))
            .height(u32::from(height));
        checked(
            self.x.configure_window(self.window, &size),
            "resize the program's window",
        );
    }

    /// Opens a plain white window of the test's own at (x, y) on the screen, over whatever is
    /// there (no window manager moves it), and waits until the X server has mapped it.
    pub fn open_window(&self, x: i16, y: i16, width: u16, height: u16) -> u32 {
        let id = self.x.generate_id().expect("an X id for the test's window");
        let white = CreateWindowAux::new().background_pixel(0xff_ffff);
        let class = WindowClass::INPUT_OUTPUT;
        let root = self.root;
        let create = self
            .x
            .create_window(0, id, root, x, y, width, height, 0, class, 0, &white);
        checked(create, "create the test's window");
        checked(self.x.map_window(id), "map the test's window");
        id
    }

    /// Takes one of the test's own windows away, and waits until the X server has.
    pub fn close_window(&self, id: u32) {
        self.x
            .destroy_window(id)
            .expect("the test's connection to Xvfb");
        answer(
            self.x.get_input_focus(),
            "answer after destroying the test's window",
        );
    }

    /// Asks the program's window to close, as a window manager's close button does: a
    /// WM_PROTOCOLS ClientMessage carrying WM_DELETE_WINDOW.
    pub fn send_close_request(&self) {
        let atom = |name: &[u8]| answer(self.x.intern_atom(false, name), "atom").atom;
        let (protocols, delete) = (atom(b"WM_PROTOCOLS"), atom(b"WM_DELETE_WINDOW"));
        let request = ClientMessageEvent::new(32, self.window, protocols, [delete, 0, 0, 0, 0]);
        self.x
            .send_event(false, self.window, EventMask::NO_EVENT, request)
            .and_then(|_| self.x.flush())
            .expect("the close request sent");
    }

    /// The program's exit status, if it ends within `timeout`.
    pub fn exit_within(&mut self, timeout: Duration) -> Option<ExitStatus> {
        wait_until(timeout, || {
            self.program.0.try_wait().expect("the program's status")
        })
    }

    /// The CPU time the program and the X server have used so far, in seconds.
    pub fn cpu_seconds(&self) -> (f64, f64) {
        (cpu_seconds(&self.program.0), cpu_seconds(&self.xvfb.0))
    }
}

/// The updates of the program's window, as X's DAMAGE extension reports them.
pub struct Updates<'a> {
    x: &'a RustConnection,
    damage: u32,
}

/// How often a count of the updates reads the X server's reports.
const UPDATES_POLL: Duration = Duration::from_millis(2);

impl Updates<'_> {
    /// How many updates came in the next `time`.
    pub fn count_during(&self, time: Duration) -> usize {
        self.take();
        let start = Instant::now();
        let mut count = 0;
        while start.elapsed() < time {
            sleep(UPDATES_POLL);
            count += self.take();
        }
        count
    }

    /// Waits for the next update, up to `timeout`: whether one came.
    pub fn next_within(&self, timeout: Duration) -> bool {
        self.take();
        let start = Instant::now();
        while start.elapsed() < timeout {
            sleep(UPDATES_POLL);
            if self.take() > 0 {
                return true;
            }
        }
        false
    }

    /// The frames sent since the last look. Xlib sends minifb's one XPutImage of the whole window
    /// as bands of rows, each reported apart, so a frame is counted by its top band (row 0).
    fn take(&self) -> usize {
        self.x.flush().expect("the test's connection to Xvfb");
        let mut count = 0;
        while let Some(event) = self
            .x
            .poll_for_event()
            .expect("the test's connection to Xvfb")
        {
            if let Event::DamageNotify(notify) = event {
                count += usize::from(notify.area.y == 0);
            }
        }
        count
    }
}

impl Drop for Updates<'_> {
    fn drop(&mut self) {
        let _ = self.x.damage_destroy(self.damage);
        let _ = self.x.flush();
    }
}

/// The X server's answer to a request, or a panic saying which answer it did not give.
fn answer<R: TryParse>(
    request: Result<Cookie<'_, RustConnection, R>, ConnectionError>,
    what: &str,
) -> R {
    let reply = request
        .map_err(ReplyError::from)
        .and_then(|cookie| cookie.reply());
    reply.unwrap_or_else(|error| panic!("Xvfb gave no {what}: {error}"))
}

/// Waits until the X server has done a request, or panics saying what it could not do.
fn checked(request: Result<VoidCookie<'_, RustConnection>, ConnectionError>, what: &str) {
    let done = request
        .map_err(ReplyError::from)
        .and_then(|cookie| cookie.check());
    done.unwrap_or_else(|error| panic!("Xvfb could not {what}: {error}"))
}

/// A process's user and system time from /proc/PID/stat, in seconds.
fn cpu_seconds(child: &Child) -> f64 {
    let stat = std::fs::read_to_string(format!("/proc/{}/stat", child.id()))
        .expect("the process's /proc/PID/stat (these tests need Linux)");
    // After the name in brackets: fields 3 onwards; utime and stime are fields 14 and 15.
    let after_name = &stat[stat.rfind(')').expect("a process name in brackets") + 2..];
    let fields: Vec<&str> = after_name.split(' ').collect();
    let ticks = |field: usize| fields[field - 3].parse::<f64>().expect("a tick count");
    (ticks(14) + ticks(15)) / TICKS_A_SECOND
}

/// Linux counts utime and stime in USER_HZ ticks, 100 a second on every architecture it has.
const TICKS_A_SECOND: f64 = 100.0;

/// The one sentence a missing tool fails with.
fn missing(tool: &str, error: std::io::Error) -> String {
    if error.kind() == std::io::ErrorKind::NotFound {
        format!("{tool} is not installed: these tests need Xvfb and xdotool ({INSTALL})")
    } else {
        format!("the test could not start {tool}: {error}")
    }
}

fn read_all(mut stream: impl std::io::Read) -> String {
    let mut text = String::new();
    let _ = stream.read_to_string(&mut text);
    text
}

/// The first line a stream gives, if it gives one within `timeout`.
fn read_line_within(
    stream: impl std::io::Read + Send + 'static,
    timeout: Duration,
) -> Option<String> {
    let (sender, receiver) = mpsc::channel();
    std::thread::spawn(move || {
        let mut line = String::new();
        let _ = BufReader::new(stream).read_line(&mut line);
        let _ = sender.send(line);
    });
    receiver.recv_timeout(timeout).ok()
}
