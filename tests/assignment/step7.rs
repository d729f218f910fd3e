//! Step 7: controls to move and rotate the camera: `moved`, the camera a step on with keys held.
use super::*;
use glam::{DVec2, dvec2};

/// The camera somewhere, turned and tilted.
fn somewhere() -> Camera {
    camera_at(dvec3(1.0, 0.5, -2.0), 0.7, -0.4)
}

/// A step of a tenth of a second.
const DT: f64 = 0.1;

#[test]
fn each_key_moves_or_turns_the_camera_its_way() {
    // W along the view, D to the right, R up, Left turns it left and Up tilts it up; S, A, F,
    // Right and Down the other way.
    let (step, angle) = (README_MOVE_SPEED * DT, README_TURN_SPEED * DT);
    let start = somewhere();
    let matrix = camera_matrix(start);
    for (plus, minus, way, turn) in [
        (Key::W, Key::S, -matrix.z_axis * step, DVec2::ZERO),
        (Key::D, Key::A, matrix.x_axis * step, DVec2::ZERO),
        (Key::R, Key::F, UP * step, DVec2::ZERO),
        (Key::Left, Key::Right, ORIGIN, dvec2(angle, 0.0)),
        (Key::Up, Key::Down, ORIGIN, dvec2(0.0, angle)),
    ] {
        for (key, sign) in [(plus, 1.0), (minus, -1.0)] {
            let after = moved(start, &[key], DT);
            let by = to_dvec3(after.position) - to_dvec3(start.position);
            let turned = dvec2(after.yaw - start.yaw, after.pitch - start.pitch);
            assert!(
                by.abs_diff_eq(way * sign, 1e-9) && turned.abs_diff_eq(turn * sign, 1e-9),
                "{key:?} held {DT} s should move the eye by {sign} × {way} and turn it by {sign} × {turn} radians (yaw left, pitch up), not by {by} and {turned}: look at moved."
            );
        }
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
    let after = moved(somewhere(), &[Key::Home, Key::W], DT);
    assert!(
        after == Camera::default(),
        "Home, held with W, should put the camera back at the start, (0, 0, 0) looking at (0, 0, -1), not at {} turned {} and tilted {}: look at moved.",
        to_dvec3(after.position),
        after.yaw,
        after.pitch
    );
}
