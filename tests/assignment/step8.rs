//! Step 8: a checkerboard on the floor: F = ((int)(2 λ1) + (int)λ2) & 1, unit squares here.
use super::*;

#[test]
fn a_floor_square_is_odd_where_floor_x_plus_floor_z_is_odd() {
    // Squares either side of x = 0 and z = 0, and out at the horizon.
    for (x, z) in [
        (0.5, 0.5),
        (-0.5, 0.5),
        (-0.5, -0.5),
        (1.5, -2.5),
        (3e9, 0.5),
        (-3e11, 0.5),
    ] {
        let odd = (f64::floor(x) + f64::floor(z)).rem_euclid(2.0) == 1.0;
        assert!(
            odd_square(vec3(x, -1.0, z)) == odd,
            "the floor square at x = {x}, z = {z} is odd: {odd}. Look at odd_square."
        );
    }
}

#[test]
fn odd_squares_of_a_checkered_floor_show_a_quarter_of_the_light() {
    // Lit from far straight above (N.L = 1), the odd square at x = 0.5, z = -0.5 shows a quarter
    // of white on a checkered floor, and all of it on a plain one.
    let camera = camera(dvec3(0.0, 1.0, 3.0), 0.0, -0.5);
    let pixel = pixel_of(camera, dvec3(0.5, -1.0, -0.5));
    for (checkered, share) in [(true, README_ODD_SQUARE_BRIGHTNESS), (false, 1.0)] {
        let floor = object(floor_plane(), WHITE, 0.0, checkered);
        let (green, expected) = (
            rgb(&frame(vec![floor], 1e6 * UP, camera), pixel)[1],
            bytes(WHITE * share)[1],
        );
        assert!(
            green.abs_diff(expected) <= 1,
            "the odd square at x = 0.5, z = -0.5 of a floor, checkered: {checkered}, should show green {expected}, not {green}: look at where Scene::trace uses odd_square."
        );
    }
}
