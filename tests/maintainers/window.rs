//! Step 7 tested as a user meets it: the built program in a real X server (a private Xvfb), driven
//! by real key events (xdotool) and looked at from outside, in screenshots, in its title and in
//! the updates X reports. The window's size and first frame, that a window manager may resize it,
//! the pose in the title giving the frame command the very frame shown, how far a held key moves
//! the camera, a key let go while the focus was elsewhere, every frame shown while a key is held
//! and two a second at rest, the CPU taken at rest, a covered and a resized window shown again
//! without a key press, and quitting.
//!
//! They need Xvfb and xdotool (`apt-get install xvfb xdotool`), so plain `cargo test` leaves them
//! out; `cargo test -p maintainers --test window -- --include-ignored` runs them, as CI's
//! `cargo test --workspace --no-fail-fast -- --include-ignored` does. They run one at a time (see
//! support/xwindow.rs, which starts and screenshots everything), in about a minute.
#![allow(dead_code)] // each test file uses only part of the program
include!("../../src/main.rs"); // the program itself: its items in reach with no `pub`
#[path = "support/built.rs"]
mod built; // the program and the frame command, built as `cargo build` builds them
#[path = "support/picture.rs"]
mod picture;
#[path = "support/xwindow.rs"]
mod xwindow; // Xvfb, the program, xdotool and screenshots: nothing a reader of the tests needs

use std::thread::sleep;
use std::time::Duration;
use xwindow::*;

/// How fast a held key moves and turns the camera, as the README gives it.
const README_SPEED: f64 = 2.0; // units a second
const README_TURN_SPEED: f64 = 1.5; // radians a second

/// How often the README says the window gets its frame again at rest.
const README_RESEND: Duration = Duration::from_millis(500);

#[test]
#[ignore = "needs Xvfb and xdotool (apt-get install xvfb xdotool): run with --include-ignored"]
fn the_window_is_1024x512_and_shows_the_start_frame() {
    let session = Session::start();
    let size = session.size();
    assert!(
        size == (WIDTH as u16, VIEW as u16),
        "the window should be {WIDTH}x{VIEW}, the 3D view and the map side by side, not {}x{}",
        size.0,
        size.1
    );
    shows_the_start_frame(&session);
}

#[test]
#[ignore = "needs Xvfb and xdotool (apt-get install xvfb xdotool): run with --include-ignored"]
fn the_window_lets_a_window_manager_resize_it() {
    // Xvfb has no window manager, so the resize test below resizes any window; a user's window
    // manager heeds the window's WM_NORMAL_HINTS, which must not fix its size.
    let session = Session::start();
    let fixed = session.fixed_size();
    assert!(
        fixed.is_none(),
        "the window should let a window manager resize it, as the README says; its \
         WM_NORMAL_HINTS fix its width and height at {fixed:?} (look at main's WindowOptions, \
         resize)"
    );
}

#[test]
#[ignore = "needs Xvfb and xdotool (apt-get install xvfb xdotool): run with --include-ignored"]
fn the_title_gives_the_pose_of_the_frame_the_window_shows() {
    const FORWARD: f64 = 1.0; // seconds W is held: 2 units along -z
    const TURN: f64 = 0.5; // seconds Left is held then: 0.75 radians left
    const TILT: f64 = 0.3; // seconds Up is held then: 0.45 radians up
    let session = Session::start();
    shows_the_start_frame(&session);
    let title = session.title();
    assert!(
        title.contains("raytracer") && pose_in(&title) == Some([0.0; 5]),
        "the title should name the program and give the start pose, five numbers 0 (x y z yaw \
         pitch, as the frame command takes them); it is {title:?} (look at where main sets the \
         title when it renders a frame)"
    );
    let held = [
        hold(&session, "w", FORWARD),
        hold(&session, "Left", TURN),
        hold(&session, "Up", TILT),
    ];
    let pose = resting_pose(&session).unwrap_or_else(|why| panic!("{why}"));
    let title = session.title();
    println!(
        "W held {FORWARD} s ({:.3?} from keydown to keyup), Left {TURN} s ({:.3?}), Up {TILT} s \
         ({:.3?}): {title:?}",
        held[0], held[1], held[2]
    );
    let expected = [
        0.0,
        0.0,
        -README_SPEED * FORWARD,
        README_TURN_SPEED * TURN,
        README_TURN_SPEED * TILT,
    ];
    let slack = HOLD_SLACK.as_secs_f64();
    let within = [
        TITLE_ROUNDING,
        TITLE_ROUNDING,
        README_SPEED * slack,
        README_TURN_SPEED * slack,
        README_TURN_SPEED * slack,
    ];
    let off = (0..5).any(|i| (pose[i] - expected[i]).abs() > within[i]);
    let listed = |numbers: [f64; 5]| numbers.map(|number| format!("{number:.4}")).join(" ");
    assert!(
        !off,
        "W held {FORWARD} s, then Left {TURN} s, then Up {TILT} s, should bring the title's pose \
         (x y z yaw pitch) to {}, give or take {} (the README's {README_SPEED} units and \
         {README_TURN_SPEED} radians a second); the title is {title:?}",
        listed(expected),
        listed(within)
    );
    the_frame_command_saves_the_frame_shown(&session, "after W, Left and Up");
}

#[test]
#[ignore = "needs Xvfb and xdotool (apt-get install xvfb xdotool): run with --include-ignored"]
fn off_the_map_the_title_gives_the_pose_of_the_frame_the_window_shows() {
    // S held 3 s: 6 units back, past the map's bottom edge, where the eye's marker waits whole.
    const BACK: f64 = 3.0;
    let session = Session::start();
    shows_the_start_frame(&session);
    hold(&session, "s", BACK);
    let [.., z, _, _] = resting_pose(&session).unwrap_or_else(|why| panic!("{why}"));
    let edge = MAP_CORNER.z + MAP_SIDE; // the map's bottom edge
    assert!(
        z > edge,
        "S held {BACK} s should take the eye {} units back, off the map (past z = {edge}); the \
         title is {:?}",
        README_SPEED * BACK,
        session.title()
    );
    the_frame_command_saves_the_frame_shown(&session, "off the map");
}

#[test]
#[ignore = "needs Xvfb and xdotool (apt-get install xvfb xdotool): run with --include-ignored"]
fn turned_past_a_full_turn_the_title_gives_the_yaw_within_a_turn() {
    // Left held 4.6 s: 6.9 radians, more than a full turn (2π, 6.283) by 0.617.
    const TURN: f64 = 4.6;
    let session = Session::start();
    shows_the_start_frame(&session);
    hold(&session, "Left", TURN);
    let [.., yaw, _] = resting_pose(&session).unwrap_or_else(|why| panic!("{why}"));
    let expected = (README_TURN_SPEED * TURN) % TAU;
    let within = README_TURN_SPEED * HOLD_SLACK.as_secs_f64();
    assert!(
        yaw.abs() < TAU && (yaw - expected).abs() <= within,
        "Left held {TURN} s turns the camera {:.2} radians, more than a full turn: the title \
         should give the yaw within a turn, {expected:.3} give or take {within:.3}; the title is \
         {:?} (look at where main rounds the pose for the title)",
        README_TURN_SPEED * TURN,
        session.title()
    );
    the_frame_command_saves_the_frame_shown(&session, "turned past a full turn");
}

/// The frame command run with the title's five numbers, as a user copies them, saves what the
/// window shows: SAME_FROM_THE_TITLE of its pixels exactly the window's.
fn the_frame_command_saves_the_frame_shown(session: &Session, pose: &str) {
    let title = session.title();
    let shown = session.screenshot();
    let numbers = pose_words(&title).unwrap_or_else(|| panic!("{}", no_pose(&title)));
    let path = std::env::temp_dir().join(format!("raytracer-window-{}.png", std::process::id()));
    let file = path.to_str().expect("a temporary path that is text");
    let output = std::process::Command::new(&built::built().frame)
        .args(&numbers)
        .arg(file)
        .output()
        .expect("the test could not start the frame command");
    let command = format!(
        "`cargo run --example frame -- {} FILE.png`",
        numbers.join(" ")
    );
    assert!(
        output.status.success(),
        "{pose}, the title is {title:?}: {command} should save the frame; it said: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    let read = picture::read_png(file);
    std::fs::remove_file(&path).ok();
    let ((width, height), saved) = read.unwrap_or_else(|error| panic!("{error}"));
    let window = picture::rgb_bytes(&shown.pixels);
    let same = saved
        .chunks(3)
        .zip(window.chunks(3))
        .filter(|(a, b)| a == b)
        .count();
    let share = same as f64 / (WIDTH * VIEW) as f64;
    println!(
        "{pose}, {title:?}: the frame command's PNG has {:.3}% of the window's pixels",
        100.0 * share
    );
    let sizes = [
        (width as usize, height as usize),
        (shown.width, shown.height),
    ];
    assert!(
        sizes == [(WIDTH, VIEW); 2] && share >= SAME_FROM_THE_TITLE,
        "{pose}, {command} with the title's numbers should save the frame the window shows (the \
         window renders the pose the title gives, to 3 decimals); {:.3}% of the pixels are the \
         same, not at least {}% (the PNG is {width}x{height}, the window {}x{}; the title is \
         {title:?}: look at where main rounds the pose, renders it and sets the title)",
        100.0 * share,
        100.0 * SAME_FROM_THE_TITLE,
        shown.width,
        shown.height
    );
}

/// How far the title's numbers may be from the pose: half their last decimal.
const TITLE_ROUNDING: f64 = 0.0005;

/// The share of the window's pixels the frame command's PNG from the title must have exactly: all
/// of them, as the window renders the very pose the title gives. Ten runs with a busy loop on each
/// core gave 100% at all three poses; a window rendering the pose before its rounding for the
/// title gave 97.3% after W, Left and Up, 99.06% turned past a full turn and 99.96% off the map.
const SAME_FROM_THE_TITLE: f64 = 1.0;

/// How much longer or shorter a hold may count than the time between xdotool's keydown and keyup:
/// the keys are read once a step, and xdotool takes a moment to start. With a busy loop on each
/// core, ten runs counted up to 0.05 s more.
const HOLD_SLACK: Duration = Duration::from_millis(150);

#[test]
#[ignore = "needs Xvfb and xdotool (apt-get install xvfb xdotool): run with --include-ignored"]
fn a_key_held_twice_as_long_moves_the_camera_twice_as_far_at_the_readmes_speed() {
    // W for 1.5 s, then 3 s: 3 and 6 units along -z, the view's direction at the start.
    const T: f64 = 1.5;
    let session = Session::start();
    shows_the_start_frame(&session);
    let (mut distances, mut held) = (Vec::new(), Vec::new());
    for seconds in [T, 2.0 * T] {
        held.push(hold(&session, "w", seconds));
        let pose = resting_pose(&session).unwrap_or_else(|why| panic!("{why}"));
        let [x, y, z, yaw, pitch] = pose;
        assert!(
            [x, y, yaw, pitch] == [0.0; 4],
            "W should move the camera straight along its view, -z, from the start pose; the \
             title is {:?}",
            session.title()
        );
        distances.push(-z);
        session.press("Home");
        let back = wait_until(Duration::from_secs(5), || {
            let home = pose_in(&session.title()) == Some([0.0; 5]);
            (home && differences(&session.screenshot(), start_frame()) == (0, 0)).then_some(())
        });
        assert!(
            back.is_some(),
            "Home should bring the camera back to the start within 5 s, the title giving 0 0 0 \
             0 0 and the window the start frame; the title is {:?}",
            session.title()
        );
    }
    println!(
        "W held {T} s ({:.3?} from keydown to keyup) moved the camera {:.3} units, held {} s \
         ({:.3?}) {:.3} units",
        held[0],
        distances[0],
        2.0 * T,
        held[1],
        distances[1]
    );
    for (seconds, distance) in [T, 2.0 * T].into_iter().zip(&distances) {
        let expected = README_SPEED * seconds;
        assert!(
            (distance - expected).abs() <= SPEED_TOLERANCE * expected,
            "W held {seconds} s should move the camera {expected} units, the README's \
             {README_SPEED} units a second, give or take {}%; it moved it {distance:.3} units",
            SPEED_TOLERANCE * 100.0
        );
    }
    let ratio = distances[1] / distances[0];
    assert!(
        (ratio - 2.0).abs() <= 2.0 * SPEED_TOLERANCE,
        "W held twice as long should move the camera twice as far, give or take {}%; it moved it \
         {ratio:.3} times as far ({:.3} and {:.3} units)",
        SPEED_TOLERANCE * 100.0,
        distances[0],
        distances[1]
    );
}

/// How far a held key's distance may be from the README's speed × the time it was held, as a
/// share. The keys are read once a step, so a hold counts from the step before the press to the
/// last step before the release, a step off either way (1/60 s at rest), and xdotool takes a
/// moment to start: with a busy loop on each core, ten runs came within 4% (3.3% on 2026-12-03).
/// (Under heavier load, a release build beside them, steps stretched to 0.8 s and the 3 s hold
/// fell 15% short.)
const SPEED_TOLERANCE: f64 = 0.1;

#[test]
#[ignore = "needs Xvfb and xdotool (apt-get install xvfb xdotool): run with --include-ignored"]
fn a_key_let_go_while_the_focus_was_elsewhere_stops_the_camera_and_works_again_later() {
    let session = Session::start();
    shows_the_start_frame(&session);
    let elsewhere = session.open_window(0, 0, 100, 100); // beside ours, not over it
    let z = || pose_now(&session)[2];
    session.key_down("w");
    let moving = wait_until(Duration::from_secs(5), || (z() != 0.0).then_some(()));
    assert!(
        moving.is_some(),
        "W held in the window should move the camera within 5 s; the title is {:?}",
        session.title()
    );
    session.focus(elsewhere);
    let focus_left = z();
    session.key_up("w"); // X tells only the window with the focus, the test's own
    // From when the focus left, the program ignores W, which it believes is still held; without
    // that the camera would go on for ever.
    let stopped = resting_pose(&session).unwrap_or_else(|why| {
        panic!(
            "the camera should stop when the focus leaves the window with W held, and W is let go \
             in another window: {why} (look at keys_down, which should leave out keys held since \
             the focus left)"
        )
    })[2];
    let went_on = focus_left - stopped;
    assert!(
        went_on <= AFTER_THE_FOCUS_LEFT,
        "the camera should stop when the focus leaves the window with W held; it went on \
         {went_on:.2} units, from z = {focus_left} to {stopped} (look at keys_down, which should \
         leave out keys held since the focus left)"
    );
    // The whole window, not just the title: nothing else moves either.
    let at_rest = session.screenshot();
    sleep(Duration::from_secs(1));
    let (view, map) = differences(&session.screenshot(), &at_rest.pixels);
    assert!(
        (view, map) == (0, 0),
        "with W let go in another window the camera should stay still; a second later {view} \
         pixels of the 3D view and {map} of the map had changed"
    );
    session.focus(session.window);
    sleep(Duration::from_secs(1));
    let (view, map) = differences(&session.screenshot(), &at_rest.pixels);
    assert!(
        (view, map) == (0, 0),
        "with the focus back in the window and no key held the camera should stay still; a \
         second later {view} pixels of the 3D view and {map} of the map had changed"
    );
    // The program still has W down, as X told it nothing of the release elsewhere: the first
    // press there ends with the release it missed, and from then on W moves the camera again.
    session.press("w");
    hold(&session, "w", AGAIN);
    let again = resting_pose(&session).unwrap_or_else(|why| panic!("{why}"))[2];
    let moved = stopped - again;
    let expected = README_SPEED * AGAIN;
    assert!(
        moved >= expected / 2.0,
        "with the focus back, W pressed once and then held {AGAIN} s should move the camera \
         again, about {expected} units; it moved it {moved:.2} units (look at keys_down, which \
         should forget a key held since the focus left once it is let go)"
    );
}

/// How far the camera may still go after the focus left: half a second at 2 units a second. The
/// program sees the focus go at its next step, but a loaded machine may hold up a step.
const AFTER_THE_FOCUS_LEFT: f64 = 1.0;

/// How long W is held once the focus is back.
const AGAIN: f64 = 0.5;

#[test]
#[ignore = "needs Xvfb and xdotool (apt-get install xvfb xdotool): run with --include-ignored"]
fn while_a_key_is_held_the_window_shows_every_frame() {
    const COUNTED: Duration = Duration::from_secs(2);
    let session = Session::start();
    shows_the_start_frame(&session);
    let updates = session.watch_updates();
    session.key_down("Left"); // turning: the camera stays among the balls
    sleep(Duration::from_millis(300)); // past xdotool's start and the first steps
    let shown = updates.count_during(COUNTED);
    session.key_up("Left");
    let a_second = shown as f64 / COUNTED.as_secs_f64();
    println!("with Left held the window showed {a_second:.1} frames a second");
    assert!(
        a_second >= HELD_AT_LEAST,
        "with Left held the window should show each frame the program renders, at least \
         {HELD_AT_LEAST} a second; it showed {a_second:.1} (look at main's loop: a rendered frame \
         should be sent at once, steps_at_rest set back to 0)"
    );
}

/// Frames shown a second while a key is held, at least. A frame takes about 20 ms to render
/// here: 50 to 60 a second were shown, 30 to 40 with a busy loop on each core (ten runs; 24.5 to
/// 31 on 2026-12-03); with only the re-send sending, 2.
const HELD_AT_LEAST: f64 = 20.0;

#[test]
#[ignore = "needs Xvfb and xdotool (apt-get install xvfb xdotool): run with --include-ignored"]
fn at_rest_the_window_gets_its_frame_twice_a_second() {
    const COUNTED: Duration = Duration::from_secs(5);
    let session = Session::start();
    shows_the_start_frame(&session);
    sleep(Duration::from_secs(1)); // past the first frame's rendering and sending
    let updates = session.watch_updates();
    let a_second = updates.count_during(COUNTED) as f64 / COUNTED.as_secs_f64();
    println!("at rest the window got {a_second:.1} frames a second");
    let expected = 1.0 / README_RESEND.as_secs_f64();
    assert!(
        AT_REST_FRAMES_A_SECOND.contains(&a_second),
        "at rest the window should get its frame again {expected} times a second, as the README \
         says ({AT_REST_FRAMES_A_SECOND:?} here); it got it {a_second:.1} times (look at main's \
         loop: set_target_fps's steps a second, and RESEND_EVERY)"
    );
}

/// Frames a second at rest: 2.0 in ten runs with a busy loop on each core (1.8 to 2.0 on
/// 2026-12-03). With no cap on the steps a second minifb sends 8, and with a re-send every 2 s,
/// 0.5 (seen as 0.6).
const AT_REST_FRAMES_A_SECOND: std::ops::RangeInclusive<f64> = 1.5..=3.0;

#[test]
#[ignore = "needs Xvfb and xdotool (apt-get install xvfb xdotool): run with --include-ignored"]
fn at_rest_the_program_and_the_x_server_take_under_3_percent_of_a_core() {
    const AT_REST: Duration = Duration::from_secs(10);
    let session = Session::start();
    shows_the_start_frame(&session);
    sleep(Duration::from_secs(1)); // past the first frame's rendering and sending
    let before = session.cpu_seconds();
    sleep(AT_REST);
    let after = session.cpu_seconds();
    let share = |used: f64| 100.0 * used / AT_REST.as_secs_f64();
    let (program, xvfb) = (share(after.0 - before.0), share(after.1 - before.1));
    println!("at rest, the program took {program:.1}% of a core and Xvfb {xvfb:.1}%");
    assert!(
        program + xvfb < 3.0,
        "at rest the program and the X server together should take under 3% of a core; over \
         {AT_REST:?} the program took {program:.1}% and Xvfb {xvfb:.1}%"
    );
}

#[test]
#[ignore = "needs Xvfb and xdotool (apt-get install xvfb xdotool): run with --include-ignored"]
fn a_window_uncovered_shows_its_frame_again_within_half_a_second() {
    let session = Session::start();
    shows_the_start_frame(&session);
    let (x, y) = session.position();
    let cover = session.open_window(x + 100, y + 100, 600, 300); // over both halves
    let under_the_cover = || session.screenshot().at(400, 250);
    let covered = wait_until(Duration::from_secs(5), || {
        (under_the_cover() == 0xff_ffff).then_some(())
    });
    assert!(
        covered.is_some(),
        "the test's white window should cover the program's window at (400, 250) within 5 s; it \
         shows {:06x} there",
        under_the_cover()
    );
    // Uncovered just after a re-send, the worst time: the next comes a whole period later.
    let updates = session.watch_updates();
    assert!(
        updates.next_within(Duration::from_secs(2)),
        "at rest the window should get its frame again twice a second; none came in 2 s (look \
         at RESEND_EVERY)"
    );
    session.close_window(cover);
    let uncovered = Instant::now();
    // Xvfb keeps nothing of a covered window: the uncovered part is black until the frame comes.
    let repaired = wait_until(UNCOVERED_WITHIN, || {
        (differences(&session.screenshot(), start_frame()) == (0, 0)).then(|| uncovered.elapsed())
    });
    let Some(took) = repaired else {
        let (view, map) = differences(&session.screenshot(), start_frame());
        panic!(
            "uncovered just after a re-send, the window should show its frame again within the \
             README's {README_RESEND:?} (the test allows {UNCOVERED_WITHIN:?}); {view} pixels of \
             the 3D view and {map} of the map still differ from it (look at RESEND_EVERY)"
        );
    };
    println!("the window uncovered just after a re-send showed its frame again after {took:.2?}");
}

/// The README's half a second, and what a loaded machine adds: with a busy loop on each core, ten
/// runs saw the frame after 0.54 to 0.55 s (a screenshot every 50 ms; on 2026-12-03, 0.51 to
/// 0.56 s, and once 0.07 s).
const UNCOVERED_WITHIN: Duration = Duration::from_millis(800);

#[test]
#[ignore = "needs Xvfb and xdotool (apt-get install xvfb xdotool): run with --include-ignored"]
fn a_resized_window_shows_the_frame_scaled_to_fit_within_a_quarter_of_a_second() {
    let session = Session::start();
    shows_the_start_frame(&session);
    let updates = session.watch_updates();
    // Taller than 2:1, black bars above and below; wider, black bars left and right; larger.
    for (width, height) in [(800, 600), (1000, 300), (1100, 700)] {
        // Resized just after a re-send, so that the re-send cannot be what shows it in time.
        assert!(
            updates.next_within(Duration::from_secs(2)),
            "at rest the window should get its frame again twice a second; none came in 2 s \
             (look at RESEND_EVERY)"
        );
        session.resize(width, height); // as a window manager does for a user
        let resized = Instant::now();
        assert!(
            session.size() == (width, height),
            "the window should now be {width}x{height}; it is {:?}",
            session.size()
        );
        // No key pressed: the program must see the new size and send the frame again.
        let shown = wait_until(RESIZED_WITHIN, || {
            scaled_mismatches(&session.screenshot())
                .is_none()
                .then(|| resized.elapsed())
        });
        let Some(took) = shown else {
            let mismatches = scaled_mismatches(&session.screenshot()).unwrap_or_default();
            panic!(
                "{RESIZED_WITHIN:?} after the window was made {width}x{height} it should show the \
                 frame scaled to fit, 2:1 kept, centred between black bars; {mismatches} (look at \
                 main's loop, which should send the frame again when the window's size changes, \
                 and at WindowOptions' scale_mode)"
            );
        };
        println!("the window made {width}x{height} showed the scaled frame after {took:.2?}");
    }
}

/// A resized window is black until the frame comes: with a busy loop on each core, ten runs saw
/// it after 0.05 to 0.13 s (a screenshot every 50 ms; 0.05 to 0.08 s looking without a pause;
/// 0.06 to 0.16 s on 2026-12-03).
/// Resized just after a re-send, with only the re-send to show it, it came half a second later.
const RESIZED_WITHIN: Duration = Duration::from_millis(250);

#[test]
#[ignore = "needs Xvfb and xdotool (apt-get install xvfb xdotool): run with --include-ignored"]
fn escape_quits_with_status_0() {
    let mut session = Session::start();
    shows_the_start_frame(&session);
    session.press("Escape");
    let status = session.exit_within(Duration::from_secs(5));
    assert!(
        status.is_some_and(|status| status.code() == Some(0)),
        "Escape should quit the program with status 0 within 5 s; its status: {status:?}"
    );
}

#[test]
#[ignore = "needs Xvfb and xdotool (apt-get install xvfb xdotool): run with --include-ignored"]
fn a_close_request_quits_with_status_0() {
    let mut session = Session::start();
    shows_the_start_frame(&session);
    session.send_close_request(); // WM_DELETE_WINDOW, as a window manager's close button sends
    let status = session.exit_within(Duration::from_secs(5));
    assert!(
        status.is_some_and(|status| status.code() == Some(0)),
        "a close request should quit the program with status 0 within 5 s; its status: {status:?}"
    );
}

// What the tests compare the window with.

/// The frame `render` makes for the demo's start pose.
fn start_frame() -> &'static [u32] {
    static FRAME: std::sync::OnceLock<Vec<u32>> = std::sync::OnceLock::new();
    FRAME.get_or_init(|| {
        let mut frame = vec![0; WIDTH * VIEW];
        render(&Scene::demo(), &Camera::default(), &mut frame);
        frame
    })
}

/// Waits up to 10 s for the window to show the start frame, pixel for pixel.
fn shows_the_start_frame(session: &Session) {
    let shown = wait_until(Duration::from_secs(10), || {
        (differences(&session.screenshot(), start_frame()) == (0, 0)).then_some(())
    });
    if shown.is_none() {
        let (view, map) = differences(&session.screenshot(), start_frame());
        panic!(
            "the window should show the frame render makes for the start pose; after 10 s, {view} \
             of the 3D view's pixels and {map} of the map's differ from it"
        );
    }
}

/// How many pixels of a 1024x512 screenshot differ from a frame, in the 3D view and in the map.
fn differences(shown: &Image, frame: &[u32]) -> (usize, usize) {
    if (shown.width, shown.height) != (WIDTH, VIEW) {
        return (VIEW * VIEW, VIEW * VIEW);
    }
    let differ = |half: std::ops::Range<usize>| {
        let rows = shown.pixels.chunks(WIDTH).zip(frame.chunks(WIDTH));
        rows.map(|(shown, frame)| half.clone().filter(|&x| shown[x] != frame[x]).count())
            .sum()
    };
    (differ(0..VIEW), differ(VIEW..WIDTH))
}

/// Holds a key down for `seconds`: how long from before xdotool's keydown to after its keyup.
fn hold(session: &Session, key: &str, seconds: f64) -> Duration {
    let pressed = Instant::now();
    session.key_down(key);
    sleep(Duration::from_secs_f64(seconds));
    session.key_up(key);
    pressed.elapsed()
}

/// The five numbers a title gives, x y z yaw pitch, as written there.
fn pose_words(title: &str) -> Option<Vec<&str>> {
    let is_number = |word: &&str| word.parse::<f64>().is_ok_and(f64::is_finite);
    let numbers: Vec<&str> = title.split_whitespace().filter(is_number).collect();
    (numbers.len() == 5).then_some(numbers)
}

/// The pose a title gives: its five numbers, x y z yaw pitch, as the frame command takes them.
fn pose_in(title: &str) -> Option<[f64; 5]> {
    let numbers = pose_words(title)?.into_iter().map(|word| word.parse().ok());
    numbers.collect::<Option<Vec<f64>>>()?.try_into().ok()
}

/// The pose the title gives now.
fn pose_now(session: &Session) -> [f64; 5] {
    let title = session.title();
    pose_in(&title).unwrap_or_else(|| panic!("{}", no_pose(&title)))
}

/// The pose in the title once the camera has stopped: the title the same for a second (twice the
/// re-send's half second), within 10 s; else a sentence on what the title is. A heavily loaded
/// machine held the program's steps up for as much as 0.8 s (measured), so a title unchanged in
/// two looks a moment apart may be one between steps.
fn resting_pose(session: &Session) -> Result<[f64; 5], String> {
    let mut last = (session.title(), Instant::now()); // the title, and since when
    let rest = wait_until(Duration::from_secs(10), || {
        let now = session.title();
        if now != last.0 {
            last = (now, Instant::now());
        }
        (last.1.elapsed() >= Duration::from_secs(1)).then_some(())
    });
    let title = last.0;
    match (rest, pose_in(&title)) {
        (_, None) => Err(no_pose(&title)),
        (None, Some(_)) => Err(format!(
            "with no key held the camera should stop, and the title with it; 10 s on the title \
             still changes, now {title:?}"
        )),
        (Some(()), Some(pose)) => Ok(pose),
    }
}

/// The sentence a title without the pose fails with.
fn no_pose(title: &str) -> String {
    format!(
        "the title should give the camera's pose as five numbers, x y z yaw pitch as the frame \
         command takes them; it is {title:?} (look at where main sets the title when it renders \
         a frame)"
    )
}

/// What differs between a resized window and the frame scaled to fit it, 2:1 kept, centred:
/// the frame's colour at points where 5x5 pixels of it are one colour (wherever the scaler's
/// rounding puts them), and black bars around it. None if nothing differs.
fn scaled_mismatches(shown: &Image) -> Option<String> {
    let frame = start_frame();
    let (width, height) = (shown.width as f64, shown.height as f64);
    let scale = f64::min(width / WIDTH as f64, height / VIEW as f64);
    let left = (width - WIDTH as f64 * scale) / 2.0;
    let top = (height - VIEW as f64 * scale) / 2.0;
    let (mut points, mut wrong) = (0, 0);
    for y in (2..VIEW - 2).step_by(8) {
        for x in (2..WIDTH - 2).step_by(8) {
            let color = frame[y * WIDTH + x];
            let uniform =
                (y - 2..=y + 2).all(|y| (x - 2..=x + 2).all(|x| frame[y * WIDTH + x] == color));
            if uniform {
                let at_x = left + (x as f64 + 0.5) * scale;
                let at_y = top + (y as f64 + 0.5) * scale;
                points += 1;
                wrong += usize::from(shown.at(at_x as usize, at_y as usize) != color);
            }
        }
    }
    let in_frame = |x: f64, y: f64| {
        (left - 1.0..left + WIDTH as f64 * scale + 1.0).contains(&x)
            && (top - 1.0..top + VIEW as f64 * scale + 1.0).contains(&y)
    };
    let mut bars = 0;
    let mut not_black = 0;
    for y in 0..shown.height {
        for x in 0..shown.width {
            if !in_frame(x as f64 + 0.5, y as f64 + 0.5) {
                bars += 1;
                not_black += usize::from(shown.at(x, y) != 0);
            }
        }
    }
    (wrong > 0 || not_black > 0).then(|| {
        format!(
            "{wrong} of {points} points of the frame show another colour at their scaled place \
             and {not_black} of the bars' {bars} pixels are not black"
        )
    })
}
