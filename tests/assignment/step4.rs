//! Step 4: a primary ray for each pixel: through p(u, v) = p0 + u(p1 - p0) + v(p2 - p0) on the
//! screen, turned by the camera matrix, from O = E.
use super::*;

#[test]
fn each_pixels_ray_leaves_the_eye_through_the_pixels_centre_on_the_screen() {
    // The eye at (1, 2, 3), turned 0.7 left and tilted 0.4 down: the ray through the centre of the
    // bottom left pixel, (0.5, VIEW - 0.5) from the top left.
    let camera = camera_at(dvec3(1.0, 2.0, 3.0), 0.7, -0.4);
    let (x, y) = (0.5, VIEW as f64 - 0.5);
    let ray = camera.primary_ray(x, y);
    let [origin, direction] = [ray.origin, ray.direction].map(to_dvec3);
    let expected = through(camera, x, y).normalize();
    assert!(
        origin == dvec3(1.0, 2.0, 3.0) && direction.abs_diff_eq(expected, 1e-9),
        "the eye at (1, 2, 3) turned 0.7 left and 0.4 down: the ray through ({x}, {y}) should leave it along {expected}, not {origin} along {direction}: look at Camera::axes and primary_ray."
    );
}

#[test]
fn a_level_cameras_middle_row_never_meets_the_floor() {
    // Its rays are level, so never come down to the floor below the eye. In this pose, working
    // the screen out in the world (C = E + dV, D = p(u, v) - E) tilts the row down by rounding.
    let camera = camera_at(dvec3(-1.9, 0.18, 0.07), 0.03, 0.0);
    for x in 0..VIEW {
        let ray = camera.primary_ray(x as f64 + 0.5, HALF);
        assert!(
            floor_plane().intersect(&ray).is_none(),
            "a level camera: the middle row's ray {x} meets the floor, so the map draws it as a hit far off (yellow), not a miss (sky blue). Keep C, p0, p1 and p2 relative to the eye (C = dV, D = p(u, v)), as primary_ray does, and E only as the ray's origin: in the world, rounding tilts the row."
        );
    }
}
