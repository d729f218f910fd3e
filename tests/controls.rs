//! Step 7, the controls: what each key does to the camera in a step of the window's loop, and the
//! one line the program says when it can open no window.
#![allow(dead_code)] // each test file uses only part of the program
include!("../src/main.rs"); // the program itself: its items in reach with no `pub`
#[path = "support/scenes.rs"]
mod scenes;

use scenes::*;

use std::process::Command;

/// A camera away from the start, turned and tilted, so that each direction is a different one.
fn somewhere() -> Camera {
    camera_at(v3(1.0, 0.5, -2.0), 0.7, -0.4)
}

/// A step of a tenth of a second.
const DT: f64 = 0.1;

/// How far two figures worked out in different orders may differ by rounding: far less than this.
const ROUNDING: f64 = 1e-9;

/// Are two points the same, give or take rounding?
fn same(a: V3, b: V3) -> bool {
    (a - b).length() < ROUNDING
}

#[test]
fn w_and_s_move_forward_and_back_along_the_view() {
    let camera = somewhere();
    let (view, ..) = camera_axes(&camera);
    for (keys, sign) in [([Key::W], 1.0), ([Key::S], -1.0)] {
        let expected = eye(&camera) + view * (sign * README_MOVE_SPEED * DT);
        let after = moved(camera, &keys, DT);
        assert!(
            same(eye(&after), expected),
            "{keys:?} for {DT} s should move the eye to {expected:?}, not {:?}. {}",
            after.position,
            holds(&[SPEED_FIGURE])
        );
    }
}

#[test]
fn a_and_d_move_left_and_right_level() {
    let camera = somewhere();
    let (_, right, _) = camera_axes(&camera);
    for (keys, sign) in [([Key::D], 1.0), ([Key::A], -1.0)] {
        let expected = eye(&camera) + right * (sign * README_MOVE_SPEED * DT);
        let after = moved(camera, &keys, DT);
        assert!(
            same(eye(&after), expected),
            "{keys:?} for {DT} s should move the eye to {expected:?}, not {:?}. {}",
            after.position,
            holds(&[SPEED_FIGURE])
        );
    }
}

#[test]
fn r_and_f_move_straight_up_and_down() {
    let camera = somewhere();
    for (keys, sign) in [([Key::R], 1.0), ([Key::F], -1.0)] {
        let expected = eye(&camera) + v3(0.0, sign * README_MOVE_SPEED * DT, 0.0);
        let after = moved(camera, &keys, DT);
        assert!(
            same(eye(&after), expected),
            "{keys:?} for {DT} s should move the eye to {expected:?}, not {:?}. {}",
            after.position,
            holds(&[SPEED_FIGURE])
        );
    }
}

#[test]
fn the_arrows_turn_left_and_right_and_tilt_up_and_down() {
    let camera = somewhere();
    let turn = README_TURN_SPEED * DT;
    let cases = [
        (Key::Left, camera.yaw + turn, camera.pitch),
        (Key::Right, camera.yaw - turn, camera.pitch),
        (Key::Up, camera.yaw, camera.pitch + turn),
        (Key::Down, camera.yaw, camera.pitch - turn),
    ];
    for (key, yaw, pitch) in cases {
        let after = moved(camera, &[key], DT);
        assert!(
            (after.yaw - yaw).abs() < ROUNDING && (after.pitch - pitch).abs() < ROUNDING,
            "{key:?} for {DT} s should turn the camera to yaw {yaw:.3}, pitch {pitch:.3}, not \
             yaw {:.3}, pitch {:.3}. {}",
            after.yaw,
            after.pitch,
            holds(&[SPEED_FIGURE])
        );
        assert!(
            after.position == camera.position,
            "{key:?} should not move the eye, but moved it to {:?}",
            after.position
        );
    }
}

#[test]
fn a_pair_of_opposite_keys_held_together_cancel_out() {
    let camera = somewhere();
    let pairs = [
        [Key::W, Key::S],
        [Key::A, Key::D],
        [Key::R, Key::F],
        [Key::Left, Key::Right],
        [Key::Up, Key::Down],
    ];
    for keys in pairs {
        let after = moved(camera, &keys, DT);
        assert!(
            after == camera,
            "{keys:?} held together moved the camera to {after:?}"
        );
    }
}

#[test]
fn tilting_stops_at_straight_up_and_straight_down() {
    // Held for LONG_HOLD seconds, the tilt would reach 15 radians at README_TURN_SPEED: far past π/2.
    const LONG_HOLD: f64 = 10.0;
    for (key, most) in [(Key::Up, FRAC_PI_2), (Key::Down, -FRAC_PI_2)] {
        let pitch = moved(somewhere(), &[key], LONG_HOLD).pitch;
        assert!(
            pitch == most,
            "{key:?} held for {LONG_HOLD} s should stop the tilt at {most:.4} radians, not {pitch:.4}"
        );
    }
}

#[test]
fn home_puts_the_camera_back_at_the_start() {
    let after = moved(somewhere(), &[Key::Home, Key::W], DT);
    assert!(
        after == Camera::default(),
        "Home should put the camera back at the start, not at {after:?}"
    );
}

/// Runs the built program with DISPLAY set to `display`, or unset, and returns its exit status
/// and what it wrote to stderr.
fn run(display: Option<&str>) -> (Option<i32>, String) {
    let mut command = Command::new(env!("CARGO_BIN_EXE_raytracer"));
    command.env_remove("WAYLAND_DISPLAY");
    match display {
        Some(name) => command.env("DISPLAY", name),
        None => command.env_remove("DISPLAY"),
    };
    let output = command
        .output()
        .expect("the test could not start the built program");
    let stderr = String::from_utf8_lossy(&output.stderr).into_owned();
    (output.status.code(), stderr)
}

/// What the one line says when DISPLAY is not set.
const HINT: &str = "DISPLAY is not set";

#[test]
fn without_display_set_it_says_so_in_one_line() {
    let (status, stderr) = run(None);
    assert!(
        status == Some(1),
        "with no DISPLAY the exit status should be 1, not {status:?}"
    );
    assert!(
        stderr.lines().count() == 1,
        "it should say why in one line, not: {stderr}"
    );
    assert!(
        stderr.contains(HINT),
        "the line should say that {HINT}; it says: {stderr}"
    );
}

#[test]
fn with_no_x_server_at_display_it_says_the_window_failed_in_one_line() {
    let (status, stderr) = run(Some(":4711")); // a display no X server serves
    assert!(
        status == Some(1),
        "with no X server the exit status should be 1, not {status:?}"
    );
    assert!(
        stderr.lines().count() == 1,
        "it should say why in one line, not: {stderr}"
    );
    assert!(
        !stderr.contains(HINT),
        "DISPLAY is set, yet the line says it is not: {stderr}"
    );
    assert!(
        stderr.starts_with("raytracer: ") && stderr.contains("window"),
        "the line should say, after the program's name, that the window could not be made; it \
         says: {stderr}"
    );
}
