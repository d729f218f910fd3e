//! Step 8: a checkerboard on the floor: F = ((int)(2 λ1) + (int)λ2) & 1, λ1 = x and λ2 = z. Here
//! with no 2, for unit squares, and floor for (int), which would merge the squares beside 0.
use super::*;

#[test]
fn a_floor_square_is_odd_where_floor_x_plus_floor_z_is_odd() {
    // Squares either side of x = 0 and z = 0, and out at the horizon, past an i32's range: the
    // sum of the floors, and whether it is odd.
    let squares = [
        (0.5, 0.5, false),
        (-0.5, 0.5, true),
        (-0.5, -0.5, false),
        (1.5, -1.5, true),
        (3e9, 0.5, false),
        (-3e11 - 0.5, 0.5, true),
    ];
    for (x, z, odd) in squares {
        let seen = odd_square(vec3(x, -1.0, z));
        assert!(
            seen == odd,
            "the floor square at x = {x}, z = {z} is odd: {odd}, yet odd_square says {seen}: look at odd_square (unit squares, and floor, not truncation, which merges the squares beside 0)."
        );
    }
}

#[test]
fn odd_squares_of_a_checkered_floor_show_a_quarter_of_the_light() {
    // Straight down onto the odd square x = 0.5, z = -0.5 (0 + -1 is odd), lit from high above: a
    // checkered floor shows a quarter of the light a plain one shows there.
    let [checkered, plain] = [true, false].map(|checkered| {
        traced(
            vec![object(floor_plane(), WHITE, 0.0, checkered)],
            1e6 * UP,
            dvec3(0.5, 2.0, -0.5),
            dvec3(0.5, -1.0, -0.5),
        )
    });
    let expected = plain * README_ODD_SQUARE_BRIGHTNESS;
    assert!(
        checkered.abs_diff_eq(expected, 1e-3) && plain.y > 0.5,
        "on the odd square, the checkered floor should show {expected}, a quarter of the plain floor's {plain}, not {checkered}: look at where Scene::trace uses odd_square."
    );
}
