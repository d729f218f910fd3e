//! What a user with no display meets, run as they run it: the program says so in one line and
//! points at the frame command, `cargo run --example frame`, whose PNG holds exactly the frame
//! `render` makes of the demo from the pose given, and which says in one line what is wrong with
//! its arguments. The programs are built as `cargo build` builds them (support/built.rs), so these
//! are left out of plain `cargo test`; `cargo test -p maintainers --test frame_command --
//! --include-ignored` runs them, as CI does.
#![allow(dead_code)] // each test file uses only part of the program
include!("../../src/main.rs"); // the program itself: its items in reach with no `pub`
#[path = "support/built.rs"]
mod built;
#[path = "support/picture.rs"]
mod picture;

use built::built;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::Duration;

/// The example renders one frame, and the program without a display stops at once: well under a
/// second's work. This long, they never will.
const COMMAND_LIMIT: Duration = Duration::from_secs(10);

/// Runs a built program to its end, in the folder `folder`, and what it said; fails the test if it
/// has not ended within COMMAND_LIMIT.
fn run(mut command: Command, folder: &Path, shown_as: &str) -> Output {
    let mut child = command
        .current_dir(folder)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap_or_else(|error| panic!("the test could not start {shown_as}: {error}"));
    let started = Instant::now();
    while child.try_wait().expect("the program's status").is_none() {
        if started.elapsed() > COMMAND_LIMIT {
            child.kill().ok();
            panic!(
                "{shown_as} did not finish in {} s: it renders one frame at most. Look in \
                 src/main.rs for a slip in the vector maths or a loop that never stops (draw_ray's \
                 count of dots).",
                COMMAND_LIMIT.as_secs()
            );
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    child.wait_with_output().expect("the program's output")
}

/// Runs the frame command with these arguments, in `folder`.
fn run_frame(args: &[&str], folder: &Path) -> Output {
    let mut command = Command::new(&built().frame);
    command.args(args);
    let shown_as = format!("`cargo run --example frame -- {}`", args.join(" "));
    run(command, folder, &shown_as)
}

/// A folder of the test's own in the system's temporary folder, removed when dropped.
struct Folder(PathBuf);

impl Folder {
    fn new(name: &str) -> Folder {
        let path = std::env::temp_dir().join(format!("raytracer-{}-{name}", std::process::id()));
        std::fs::create_dir_all(&path).expect("a temporary folder");
        Folder(path)
    }
}

impl Drop for Folder {
    fn drop(&mut self) {
        std::fs::remove_dir_all(&self.0).ok();
    }
}

#[test]
#[ignore = "runs the built programs (cargo build): run with --include-ignored"]
#[allow(clippy::needless_update)] // ..: any field you add to Camera as the window starts it
fn the_frame_command_writes_the_demos_frame_from_the_pose_given() {
    let folder = Folder::new("frame");
    let output = run_frame(&["0.5", "0.3", "1", "0.6", "-0.15", "frame.png"], &folder.0);
    assert!(
        output.status.success(),
        "`cargo run --example frame -- 0.5 0.3 1 0.6 -0.15 frame.png` should succeed; it said: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    let written = folder.0.join("frame.png");
    let read = picture::read_png(written.to_str().expect("a temporary path that is text"));
    let ((width, height), written) = read.unwrap_or_else(|error| panic!("{error}"));
    let camera = Camera {
        position: vec3(0.5, 0.3, 1.0),
        yaw: 0.6,
        pitch: -0.15,
        ..Camera::default()
    };
    // The example has rendered this very frame in time, so render ends here too.
    let mut expected = vec![0; WIDTH * VIEW];
    render(&Scene::demo(), &camera, &mut expected);
    assert!(
        (width, height) == (WIDTH as u32, VIEW as u32),
        "the PNG should be the window's {WIDTH} x {VIEW}, not {width} x {height}"
    );
    let differing = written
        .chunks(3)
        .zip(picture::rgb_bytes(&expected).chunks(3))
        .filter(|(a, b)| a != b)
        .count();
    assert!(
        differing == 0,
        "the PNG should be render's frame of Scene::demo from the eye at (0.5, 0.3, 1) turned 0.6 \
         and tilted -0.15; {differing} of its pixels differ (look at tests/tools/frame.rs)"
    );
}

/// The names the usage gives the arguments.
const ARGUMENT_NAMES: [&str; 6] = ["X", "Y", "Z", "YAW", "PITCH", "FILE"];

/// A line's words, its numbers and names, without the punctuation between them.
fn words(line: &str) -> Vec<&str> {
    let apart = |c: char| !c.is_alphanumeric();
    line.split(apart).filter(|word| !word.is_empty()).collect()
}

#[test]
#[ignore = "runs the built programs (cargo build): run with --include-ignored"]
fn the_frame_command_takes_any_pitch_the_title_gives() {
    // The title gives the pitch to 3 decimals, from -1.571 to 1.571 (π/2 is 1.5708).
    let folder = Folder::new("pitches");
    for pitch in ["1.5708", "-1.5708", "1.571", "-1.571"] {
        let args = ["0", "0", "0", "0", pitch, "f.png"];
        let output = run_frame(&args, &folder.0);
        assert!(
            output.status.success() && folder.0.join("f.png").exists(),
            "`cargo run --example frame -- {}` should write f.png, as the title gives a pitch up \
             to 1.571 either way; it exited with {:?} and said: {}",
            args.join(" "),
            output.status.code(),
            String::from_utf8_lossy(&output.stderr)
        );
        std::fs::remove_file(folder.0.join("f.png")).ok();
    }
}

#[test]
#[ignore = "runs the built programs (cargo build): run with --include-ignored"]
fn the_frame_command_says_in_one_line_what_is_wrong_with_its_arguments() {
    // Each line names what is wrong first: the count, or the argument (the usage after it names
    // them all).
    let folder = Folder::new("arguments");
    for (args, wrong) in [
        (&["0"][..], "1 argument"),
        (&["0", "zero", "0", "0", "0", "x.png"], "Y"),
        (&["0", "0", "0", "0", "2", "x.png"], "PITCH"),
        (&["0", "0", "0", "0", "0", "x.jpg"], "FILE"),
    ] {
        let output = run_frame(args, &folder.0);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(
            output.status.code() == Some(2) && stderr.lines().count() == 1,
            "with the arguments {args:?} the example should exit with status 2 and one line; it \
             exited with {:?} and said: {stderr}",
            output.status.code()
        );
        let said = words(&stderr);
        let first_named = said.iter().find(|word| ARGUMENT_NAMES.contains(word));
        let names_it = match wrong.split_once(' ') {
            Some((count, noun)) => said.windows(2).any(|pair| pair == [count, noun]),
            None => first_named == Some(&wrong),
        };
        assert!(
            names_it,
            "with the arguments {args:?} the line should say \"{wrong}\" before anything else it \
             names; it says: {stderr}"
        );
        let written = std::fs::read_dir(&folder.0)
            .expect("the test's folder")
            .count();
        assert!(
            written == 0,
            "with the arguments {args:?} the example should write no file; it wrote {written}"
        );
    }
}

/// Runs the program with DISPLAY set to `display`, or unset, and no WAYLAND_DISPLAY: its exit
/// status and what it said on stderr.
fn run_without_a_display(display: Option<&str>) -> (Option<i32>, String) {
    let mut command = Command::new(&built().raytracer);
    command.env_remove("WAYLAND_DISPLAY");
    match display {
        Some(name) => command.env("DISPLAY", name),
        None => command.env_remove("DISPLAY"),
    };
    let folder = std::env::temp_dir();
    let output = run(
        command,
        &folder,
        &format!("the program with DISPLAY {display:?}"),
    );
    let stderr = String::from_utf8_lossy(&output.stderr).into_owned();
    (output.status.code(), stderr)
}

#[test]
#[ignore = "runs the built programs (cargo build): run with --include-ignored"]
fn with_no_display_the_program_says_why_in_one_line_and_points_at_the_frame_command() {
    // DISPLAY unset, empty, and naming a display no X server serves.
    for (display, shown) in [
        (None, "DISPLAY is \"\""),
        (Some(""), "DISPLAY is \"\""),
        (Some(":4711"), "DISPLAY is \":4711\""),
    ] {
        let (status, stderr) = run_without_a_display(display);
        let case = match display {
            None => "with DISPLAY not set".to_string(),
            Some(name) => format!("with DISPLAY={name:?} and no X server there"),
        };
        assert!(
            status == Some(1) && stderr.lines().count() == 1,
            "{case} the program should say why in one line and exit with status 1; it exited \
             with {status:?} and said: {stderr}"
        );
        assert!(
            stderr.contains(shown) && stderr.contains("cargo run --example frame"),
            "{case} the line should say {shown} and point at `cargo run --example frame`, which \
             saves the frame with no display; it says: {stderr}"
        );
    }
}
