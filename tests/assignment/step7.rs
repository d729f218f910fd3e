//! Step 7: controls to move and rotate the camera: `moved`, the camera a step on with keys held.
use super::*;

/// The camera somewhere, turned and tilted.
fn somewhere() -> Camera {
    camera_at(dvec3(1.0, 0.5, -2.0), 0.7, -0.4)
}

/// A step of a tenth of a second.
const DT: f64 = 0.1;

/// A camera's x, y, z, yaw and pitch.
fn pose(camera: Camera) -> [f64; 5] {
    let Vec3 { x, y, z } = camera.position;
    [x, y, z, camera.yaw, camera.pitch]
}

#[test]
fn w_d_and_r_move_the_eye_along_the_view_to_the_right_and_up() {
    // (S, A and F, which move it back, cancel them out below.)
    let matrix = camera_matrix(somewhere());
    for (key, way) in [
        (Key::W, -matrix.z_axis),
        (Key::D, matrix.x_axis),
        (Key::R, UP),
    ] {
        let expected = way * README_MOVE_SPEED * DT;
        let by = to_dvec3(moved(somewhere(), &[key], DT).position) - to_dvec3(somewhere().position);
        assert!(
            by.abs_diff_eq(expected, 1e-9),
            "{key:?} held {DT} s should move the eye by {expected}, not {by}: look at moved."
        );
    }
}

#[test]
fn left_and_up_turn_the_camera_left_and_tilt_it_up() {
    // (Right and Down, which turn it back, cancel them out below.)
    let angle = README_TURN_SPEED * DT;
    for (key, left, up) in [(Key::Left, angle, 0.0), (Key::Up, 0.0, angle)] {
        let Camera { yaw, pitch, .. } = moved(somewhere(), &[key], DT);
        let [turned, tilted] = [yaw - somewhere().yaw, pitch - somewhere().pitch];
        assert!(
            (turned - left).abs() < 1e-9 && (tilted - up).abs() < 1e-9,
            "{key:?} held {DT} s should turn the camera {left} radians left and tilt it {up} up, not {turned} and {tilted}: look at moved."
        );
    }
}

#[test]
fn opposite_keys_held_together_cancel_out() {
    let pairs = [
        [Key::W, Key::S],
        [Key::D, Key::A],
        [Key::R, Key::F],
        [Key::Left, Key::Right],
        [Key::Up, Key::Down],
    ];
    for keys in pairs {
        let [before, after] = [somewhere(), moved(somewhere(), &keys, DT)].map(pose);
        assert!(
            before
                .iter()
                .zip(after)
                .all(|(before, after)| (before - after).abs() < 1e-9),
            "{keys:?} held together should leave the camera's x, y, z, yaw and pitch at {before:?}, not take them to {after:?}: look at moved."
        );
    }
}

#[test]
fn tilting_stops_at_straight_up_and_straight_down() {
    for (key, most) in [(Key::Up, FRAC_PI_2), (Key::Down, -FRAC_PI_2)] {
        let pitch = moved(somewhere(), &[key], 10.0).pitch; // held 10 s: 15 radians' worth
        assert!(
            pitch == most,
            "{key:?} held 10 s should stop the tilt at {most} radians, not {pitch}: look at moved."
        );
    }
}

#[test]
fn home_puts_the_camera_back_at_the_start_whatever_else_is_held() {
    let after = pose(moved(somewhere(), &[Key::Home, Key::W], DT));
    assert!(
        after == pose(Camera::default()),
        "Home, held with W, should put the camera back at the start, (0, 0, 0) looking at (0, 0, -1), not at x, y, z, yaw and pitch {after:?}: look at moved."
    );
}
