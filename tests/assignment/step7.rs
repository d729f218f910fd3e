//! Step 7: controls to move and rotate the camera: `moved`, the camera a step on with keys held.
use super::*;

/// The camera somewhere, turned and tilted, and a step of a tenth of a second.
fn start() -> Camera {
    camera(dvec3(1.0, 0.5, -2.0), 0.7, -0.4)
}
const DT: f64 = 0.1;

#[test]
fn w_d_and_r_move_the_eye_along_the_view_to_the_right_and_up() {
    // (S, A and F, which move it back, cancel them out below.)
    let (right, view) = (turn(start()).x_axis, -turn(start()).z_axis);
    for (key, way) in [(Key::W, view), (Key::D, right), (Key::R, UP)] {
        let expected = way * README_MOVE_SPEED * DT;
        let by = to_dvec3(moved(start(), &[key], DT).position) - to_dvec3(start().position);
        assert!(
            by.abs_diff_eq(expected, 1e-9),
            "{key:?} held {DT} s should move the eye by {expected}, not {by}: look at moved."
        );
    }
}

#[test]
fn left_and_up_turn_the_camera_left_and_tilt_it_up() {
    // (Right and Down, which turn it back, cancel them out below.)
    let turn = README_TURN_SPEED * DT;
    for (key, left, up) in [(Key::Left, turn, 0.0), (Key::Up, 0.0, turn)] {
        let Camera { yaw, pitch, .. } = moved(start(), &[key], DT);
        let by = [yaw - start().yaw, pitch - start().pitch];
        assert!(
            (by[0] - left).abs() < 1e-9 && (by[1] - up).abs() < 1e-9,
            "{key:?} held {DT} s should turn the camera {left} radians left and tilt it {up} up, not {by:?}: look at moved."
        );
    }
}

#[test]
fn opposite_keys_held_together_cancel_out() {
    for keys in [
        [Key::W, Key::S],
        [Key::D, Key::A],
        [Key::R, Key::F],
        [Key::Left, Key::Right],
        [Key::Up, Key::Down],
    ] {
        assert!(
            moved(start(), &keys, DT) == start(),
            "{keys:?} held together should leave the camera where it is: look at moved."
        );
    }
}

#[test]
fn tilting_stops_at_straight_up_and_straight_down() {
    for (key, most) in [(Key::Up, FRAC_PI_2), (Key::Down, -FRAC_PI_2)] {
        let pitch = moved(start(), &[key], 10.0).pitch; // held 10 s: 15 radians' worth
        assert!(
            pitch == most,
            "{key:?} held 10 s should stop the tilt at {most} radians, not {pitch}: look at moved."
        );
    }
}

#[test]
fn home_puts_the_camera_back_at_the_start() {
    assert!(
        moved(start(), &[Key::Home, Key::W], DT) == Camera::default(),
        "Home should put the camera back at the start, (0, 0, 0) looking at (0, 0, -1): look at moved."
    );
}
