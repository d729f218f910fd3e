//! `cargo run --example frame`, the README's way to see a frame with no display: the PNG it writes
//! holds exactly the frame `render` makes of the demo's scene from the pose given, and a bad
//! argument gets one line, not a panic. (`cargo test` builds the example beside the tests.)
#![allow(dead_code)] // each test file uses only part of the program
include!("../src/main.rs"); // the program itself: its items in reach with no `pub`
#[path = "support/picture.rs"]
mod picture;
#[path = "support/scenes.rs"]
mod scenes;

use scenes::{camera_at, frame_of, v3};
use std::path::PathBuf;
use std::process::{Command, Output, Stdio};
use std::time::Duration;

/// The example renders one frame, well under a second's work; this long, it never will.
const COMMAND_LIMIT: Duration = Duration::from_secs(10);

/// Runs the example with these arguments. Cargo puts it in `examples/`, beside the `deps/` that
/// holds this test.
fn run_frame(args: &[&str]) -> Output {
    let test = std::env::current_exe().expect("the test's own path");
    let profile = test
        .parent()
        .and_then(|deps| deps.parent())
        .expect("the test in target/PROFILE/deps");
    let example = profile.join("examples").join("frame");
    let mut child = Command::new(&example)
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap_or_else(|error| {
            panic!(
                "the example could not be started from {}: {error}; `cargo test` builds it",
                example.display()
            )
        });
    let started = Instant::now();
    while child.try_wait().expect("the example's status").is_none() {
        if started.elapsed() > COMMAND_LIMIT {
            child.kill().ok();
            panic!(
                "`cargo run --example frame -- {}` did not finish in {} s: its one frame never \
                 ends. Look in src/main.rs for a slip in the vector maths or a loop that never \
                 stops (draw_ray's count of dots).",
                args.join(" "),
                COMMAND_LIMIT.as_secs()
            );
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    child.wait_with_output().expect("the example's output")
}

/// A file of the test's own in the system's temporary folder.
fn temporary(name: &str) -> PathBuf {
    std::env::temp_dir().join(format!("raytracer-{}-{name}", std::process::id()))
}

#[test]
fn the_frame_command_writes_the_demos_frame_from_the_pose_given() {
    let camera = camera_at(v3(0.5, 0.3, 1.0), 0.6, -0.15);
    let path = temporary("frame.png");
    let file = path.to_str().expect("a temporary path that is text");
    let output = run_frame(&["0.5", "0.3", "1", "0.6", "-0.15", file]);
    assert!(
        output.status.success(),
        "`cargo run --example frame -- 0.5 0.3 1 0.6 -0.15 FILE` should succeed; it said: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    let read = picture::read_png(file);
    std::fs::remove_file(&path).ok();
    let ((width, height), written) = read.unwrap_or_else(|error| panic!("{error}"));
    let expected = picture::rgb_bytes(&frame_of(&Scene::default(), &camera));
    assert!(
        (width, height) == (WIDTH as u32, VIEW as u32),
        "the PNG should be the window's {WIDTH} x {VIEW}, not {width} x {height}"
    );
    let differing = written
        .chunks(3)
        .zip(expected.chunks(3))
        .filter(|(a, b)| a != b)
        .count();
    assert!(
        differing == 0,
        "the PNG should be render's frame of Scene::default from the eye at (0.5, 0.3, 1) turned \
         0.6 and tilted -0.15; {differing} of its pixels differ"
    );
}

#[test]
fn the_frame_command_says_in_one_line_what_is_wrong_with_its_arguments() {
    for (args, wrong) in [
        (vec!["0", "0", "0"], "3 arguments"),
        (vec!["0", "zero", "0", "0", "0", "x.png"], "Y"),
        (vec!["0", "0", "0", "0", "2", "x.png"], "PITCH"),
    ] {
        let output = run_frame(&args);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(
            output.status.code() == Some(2) && stderr.lines().count() == 1,
            "with the arguments {args:?} the example should exit with status 2 and one line; it \
             exited with {:?} and said: {stderr}",
            output.status.code()
        );
        assert!(
            stderr.contains(wrong),
            "with the arguments {args:?} the line should name {wrong}; it says: {stderr}"
        );
    }
}
