//! Step 6: per pixel, the nearest intersection, and its colour plotted.
use super::*;

#[test]
fn the_nearest_hit_is_the_first_object_met_at_p_equals_o_plus_t_d() {
    // Straight down from (1, 2, 3), over a ball over the floor, listed in either order: the ray
    // meets the ball first, at t = 1.5 and P = (1, 0.5, 3).
    let sphere = || ball(dvec3(1.0, 0.0, 3.0), 0.5, RED, 0.0);
    for objects in [
        vec![sphere(), checkered_floor()],
        vec![checkered_floor(), sphere()],
    ] {
        let mut ray = Ray::new(vec3(1.0, 2.0, 3.0), vec3(0.0, -1.0, 0.0), f64::INFINITY);
        let point = scene(objects, UP)
            .nearest_hit(&mut ray)
            .map(|hit| to_dvec3(hit.point));
        assert!(
            point == Some(dvec3(1.0, 0.5, 3.0)) && ray.t == 1.5,
            "from (1, 2, 3) straight down, the nearest hit is the ball, at t = 1.5 and P = (1, 0.5, 3), whatever the objects' order, not at t = {} and {point:?}: look at Scene::nearest_hit.",
            ray.t
        );
    }
}

#[test]
fn each_pixel_shows_what_the_ray_through_its_centre_meets() {
    // A ball 0.01 in radius 6 out, on the ray through the centre of a pixel up and to the left:
    // that pixel shows it; the pixel as far right of the middle, the sky.
    let (x, y) = (VIEW / 4, VIEW / 3);
    let center = through(Camera::default(), x as f64 + 0.5, y as f64 + 0.5).normalize() * 6.0;
    let frame = rendered(
        vec![ball(center, 0.01, RED, 0.0)],
        ORIGIN,
        Camera::default(),
    );
    let shown = rgb(&frame, (x, y));
    let mirrored = rgb(&frame, (VIEW - 1 - x, y));
    assert!(
        is_red(shown) && mirrored.abs_diff_eq(to_dvec3(Scene::demo().sky), 1.0 / 255.0),
        "pixel ({x}, {y}) should show the red ball its centre's ray meets, not {shown}, and pixel ({}, {y}) the sky, not {mirrored}: look at render, which traces the ray through each pixel's centre.",
        VIEW - 1 - x
    );
}

#[test]
fn a_colour_brighter_than_white_shows_as_255() {
    // (0, 0, 2): blue over 1 shows as 255, ff, with nothing carried into green.
    let shown = to_rgb(vec3(0.0, 0.0, 2.0));
    assert!(
        shown == 0x0000ff,
        "the colour (0, 0, 2) should show as 0000ff, not {shown:06x}: look at to_rgb."
    );
}
