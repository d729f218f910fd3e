//! The 2D slice on the right: the plane of the screen's middle row seen from above, with the eye,
//! the screen, the light, the spheres where the plane cuts them, and every 10th ray of that row
//! with its hit, shadow and mirror rays. Each test finds, by its own geometry, where a thing must
//! be drawn, and looks for its colour there.
#![allow(dead_code)] // each test file uses only part of the program
include!("../src/main.rs"); // the program itself: its items in reach with no `pub`
#[path = "support/scenes.rs"]
mod scenes;
#[path = "support/vision.rs"]
mod vision;

use scenes::*;

/// What a test of the sampled rays adds when it fails: it finds them as the README gives them.
fn sampled_rays() -> String {
    holds(&[SAMPLED_FIGURE, SCREEN_FIGURE])
}

/// The map pixel over a world point's x and z: x to the right, -z up, from MAP_CORNER.
fn map_pixel(frame: &[u32], point: V3) -> u32 {
    let column = ((point.x - MAP_CORNER.x) * MAP_SCALE) as usize;
    let row = ((point.z - MAP_CORNER.z) * MAP_SCALE) as usize;
    frame[row * WIDTH + VIEW + column]
}

/// Is the world point's x and z on the map, at least `margin` units inside its edges?
fn inside_map(point: V3, margin: f64) -> bool {
    let inside = |w: f64, low: f64| w > low + margin && w < low + MAP_SIDE - margin;
    inside(point.x, MAP_CORNER.x) && inside(point.z, MAP_CORNER.z)
}

/// The map pixels within `pixels` map pixels of a world point's x and z (those on the map).
fn map_near(frame: &[u32], point: V3, pixels: i32) -> Vec<u32> {
    map_around(frame, point, pixels, |_| true)
}

/// The map pixels exactly `reach` map pixels from a world point's, in x or z: the ring just
/// outside a square `reach - 1` either side.
fn ring(frame: &[u32], point: V3, reach: i32) -> Vec<u32> {
    map_around(frame, point, reach, |(dx, dz)| {
        dx.abs().max(dz.abs()) == reach
    })
}

/// The map pixels up to `pixels` either side of a world point's x and z that `keep` keeps.
fn map_around(
    frame: &[u32],
    point: V3,
    pixels: i32,
    keep: impl Fn((i32, i32)) -> bool,
) -> Vec<u32> {
    let mut found = Vec::new();
    for dx in -pixels..=pixels {
        for dz in -pixels..=pixels {
            let near = point + v3(f64::from(dx), 0.0, f64::from(dz)) * (1.0 / MAP_SCALE);
            if keep((dx, dz)) && inside_map(near, 0.0) {
                found.push(map_pixel(frame, near));
            }
        }
    }
    found
}

/// The colours of some map pixels by the legend's names (others in hex), for a message.
fn named(pixels: &[u32]) -> String {
    let mut names: Vec<String> = pixels
        .iter()
        .map(
            |&pixel| match LEGEND.iter().find(|&&(_, color)| color == pixel) {
                Some((name, _)) => name.to_string(),
                None => format!("{pixel:06x}"),
            },
        )
        .collect();
    names.sort();
    names.dedup();
    names.join(", ")
}

/// Is a colour drawn within a map pixel of a world point? If not, what is there, by name.
fn drawn_near(frame: &[u32], point: V3, color: u32) -> Result<(), String> {
    let near = map_near(frame, point, 1);
    if near.contains(&color) {
        Ok(())
    } else {
        Err(format!("only {} there", named(&near)))
    }
}

/// Is a whole square of `color` drawn around a world point, `reach` map pixels either side?
fn square_at(frame: &[u32], point: V3, reach: i32, color: u32) -> Result<(), String> {
    let near = map_near(frame, point, reach);
    if near.iter().all(|&pixel| pixel == color) {
        Ok(())
    } else {
        Err(format!("there: {}", named(&near)))
    }
}

/// Two poses: the start, and one moved, turned and tilted.
fn two_poses() -> [Camera; 2] {
    [Camera::default(), camera_at(v3(0.5, 0.3, 1.0), 0.6, -0.15)]
}

#[test]
fn the_eye_is_a_pink_square_7_map_pixels_wide() {
    let scene = scene_of(vec![], v3(0.0, 5.0, 2.0));
    for camera in two_poses() {
        let frame = frame_of(&scene, &camera);
        if let Err(seen) = square_at(&frame, eye(&camera), README_MARKER_REACH, CAMERA_COLOR) {
            panic!(
                "{camera:?}: no CAMERA_COLOR square 7 map pixels wide at the eye, {seen}. {}",
                holds(&[MARKER_FIGURE])
            );
        }
        assert!(
            !ring(&frame, eye(&camera), README_MARKER_REACH + 1).contains(&CAMERA_COLOR),
            "{camera:?}: the eye's square is wider than 7 map pixels. {}",
            holds(&[MARKER_FIGURE])
        );
    }
}

#[test]
fn the_screens_middle_row_is_a_pink_line_from_c_minus_right_to_c_plus_right() {
    // C = E + dV. The row is drawn 3 map pixels from either end and halfway to it from C, and not
    // 3 map pixels past either end.
    let scene = scene_of(vec![], v3(0.0, 5.0, 2.0));
    for camera in two_poses() {
        let frame = frame_of(&scene, &camera);
        let (view, right, _) = camera_axes(&camera);
        let middle = eye(&camera) + view * README_SCREEN_DISTANCE;
        let near_end = 1.0 - 3.0 / MAP_SCALE;
        for along in [-near_end, -0.5, 0.5, near_end] {
            let on_row = middle + right * along;
            if let Err(seen) = drawn_near(&frame, on_row, CAMERA_COLOR) {
                panic!(
                    "{camera:?}: no CAMERA_COLOR on the screen's row at {on_row:?}, {seen}. {}",
                    holds(&[SCREEN_FIGURE])
                );
            }
        }
        let past_end = 1.0 + 3.0 / MAP_SCALE;
        for along in [-past_end, past_end] {
            let past = middle + right * along;
            assert!(
                drawn_near(&frame, past, CAMERA_COLOR).is_err(),
                "{camera:?}: the screen's row goes on past its end, to {past:?}. {}",
                holds(&[SCREEN_FIGURE])
            );
        }
    }
}

#[test]
fn the_light_is_an_orange_square_7_map_pixels_wide() {
    let light = v3(-2.0, 5.0, 2.0);
    let frame = frame_of(&scene_of(vec![], light), &Camera::default());
    if let Err(seen) = square_at(&frame, light, README_MARKER_REACH, LIGHT_COLOR) {
        panic!(
            "no LIGHT_COLOR square 7 map pixels wide under the light at {light:?}, {seen}. {}",
            holds(&[MARKER_FIGURE])
        );
    }
    assert!(
        !ring(&frame, light, README_MARKER_REACH + 1).contains(&LIGHT_COLOR),
        "the light's square is wider than 7 map pixels. {}",
        holds(&[MARKER_FIGURE])
    );
}

#[test]
fn off_the_map_the_eye_and_the_light_stand_whole_on_the_nearest_edge() {
    let last = (VIEW - 1) as i32;
    let reach = README_MARKER_REACH;
    // Points off the map behind it, beside it and past two corners: the marker's middle map
    // pixel, README_MARKER_REACH pixels in from each edge it is past, and its other coordinate where the
    // point is.
    let column = |x: f64| ((x - MAP_CORNER.x) * MAP_SCALE) as i32;
    let row = |z: f64| ((z - MAP_CORNER.z) * MAP_SCALE) as i32;
    let cases = [
        (
            "behind the map",
            v3(0.0, 0.0, 25.0),
            (column(0.0), last - reach),
        ),
        (
            "right of the map",
            v3(20.0, 0.0, -4.0),
            (last - reach, row(-4.0)),
        ),
        (
            "past its bottom left corner",
            v3(-30.0, 0.0, 40.0),
            (reach, last - reach),
        ),
        (
            "past its top right corner",
            v3(30.0, 0.0, -40.0),
            (last - reach, reach),
        ),
    ];
    for (place, point, (middle_x, middle_y)) in cases {
        let light_only = frame_of(&scene_of(vec![], point), &Camera::default());
        let eye_there = camera_at(point, 0.0, 0.0);
        let eye_only = frame_of(&scene_of(vec![], v3(0.0, 5.0, -3.0)), &eye_there);
        let markers = [
            ("eye", &eye_only, CAMERA_COLOR),
            ("light", &light_only, LIGHT_COLOR),
        ];
        for (what, frame, color) in markers {
            for dx in -reach..=reach {
                for dy in -reach..=reach {
                    let (x, y) = ((middle_x + dx) as usize, (middle_y + dy) as usize);
                    let seen = frame[y * WIDTH + VIEW + x];
                    assert!(
                        seen == color,
                        "the {what} {place}: its square 7 map pixels wide should be whole around \
                         map pixel ({middle_x}, {middle_y}), but ({x}, {y}) is {}. {}",
                        named(&[seen]),
                        holds(&[MARKER_FIGURE])
                    );
                }
            }
        }
    }
}

#[test]
fn a_sphere_cut_by_the_level_slice_is_outlined_in_its_colour() {
    // Its centre 0.5 below the eye: the plane y = 0 cuts it in a circle of radius √0.75. The
    // far side of that circle, which no sampled ray reaches, shows the ball's colour.
    let center = v3(2.0, -0.5, -5.0);
    let scene = scene_of(
        vec![sphere(center, 1.0, matte(PURE_RED))],
        v3(0.0, 5.0, 2.0),
    );
    let frame = frame_of(&scene, &Camera::default());
    let circle = 0.75f64.sqrt();
    for angle in [1.2f64, 1.6, 2.0] {
        let on_circle = v3(
            center.x + circle * angle.cos(),
            0.0,
            center.z - circle * angle.sin(),
        );
        if let Err(seen) = drawn_near(&frame, on_circle, pixel_of(PURE_RED)) {
            panic!("no red outline at {on_circle:?}, where y = 0 cuts the red ball: {seen}");
        }
    }
}

#[test]
fn a_tilted_slice_outlines_the_spheres_it_cuts_and_no_others() {
    for (yaw, pitch) in [(0.0, 0.25), (0.0, -0.25), (0.6, 0.3), (-0.9, -0.35)] {
        let camera = camera_at(v3(0.5, 0.3, 1.0), yaw, pitch);
        let (view, right, up) = camera_axes(&camera);
        let eye = eye(&camera);
        // Cut: its centre `height` off the tilted plane, which cuts it in a circle of radius
        // √(1 - height²) around the centre's foot on the plane.
        let height = 0.4;
        let cut_center = eye + view * 5.0 + right * 0.5 + up * height;
        let foot = cut_center - up * height;
        let circle = (1.0 - height * height).sqrt();
        // Missed: at the eye's height, where a level plane would cut it, but 5 |sin pitch| >= 1.2
        // from the tilted plane, further than its radius 0.8.
        let level_view = v3(-yaw.sin(), 0.0, -yaw.cos());
        let missed_center = eye + level_view * 5.0 - right * 2.5;
        let scene = scene_of(
            vec![
                sphere(cut_center, 1.0, matte(PURE_RED)),
                sphere(missed_center, 0.8, matte(PURE_GREEN)),
            ],
            eye - view * 3.0 + up * 4.0,
        );
        let frame = frame_of(&scene, &camera);
        // The far side of the circle (angles from right towards V), which no sampled ray reaches.
        for angle in [1.2f64, 1.57, 1.9] {
            let on_circle = foot + (right * angle.cos() + view * angle.sin()) * circle;
            if let Err(seen) = drawn_near(&frame, on_circle, pixel_of(PURE_RED)) {
                panic!(
                    "{camera:?}: no red outline at {on_circle:?}, where the tilted plane cuts the \
                     red ball: {seen}"
                );
            }
        }
        assert!(
            !map_of(&frame).contains(&pixel_of(PURE_GREEN)),
            "{camera:?}: the green ball is outlined, yet the tilted plane misses it"
        );
    }
}

#[test]
fn each_sampled_ray_that_hits_a_sphere_ends_there_with_a_dot() {
    for camera in [Camera::default(), camera_at(v3(0.5, 0.3, 1.0), 0.6, -0.3)] {
        let (view, right, up) = camera_axes(&camera);
        // A ball ahead, its centre 0.3 off the slice's plane: about a fifth of the rays hit it.
        let center = eye(&camera) + view * 4.5 + right * 0.8 + up * 0.3;
        let radius = 1.0;
        let scene = scene_of(vec![sphere(center, radius, matte(RED))], v3(0.0, 50.0, 0.0));
        let frame = frame_of(&scene, &camera);
        for direction in sampled_directions(&camera) {
            let Some(hit) = ray_sphere(eye(&camera), direction, center, radius) else {
                continue;
            };
            if let Err(seen) = square_at(&frame, hit, 1, RAY_COLOR) {
                panic!(
                    "{camera:?}: no RAY_COLOR dot 3 map pixels wide where a sampled ray hits the \
                     ball, at {hit:?}; {seen}. {}",
                    sampled_rays()
                );
            }
            // The ring of 16 map pixels around the dot: the ray coming in crosses it in at most
            // 2, a dot 5 pixels wide would fill it.
            let on_ring = ring(&frame, hit, 2)
                .iter()
                .filter(|&&pixel| pixel == RAY_COLOR)
                .count();
            assert!(
                on_ring <= 2,
                "{camera:?}: the dot at {hit:?} is wider than 3 map pixels: {on_ring} of the 16 \
                 pixels around it are RAY_COLOR, where the ray crosses 2 at most"
            );
            // Past the hit, inside the ball, the ray is not drawn on.
            let inside = hit + direction.normalize() * (0.5 * radius);
            assert!(
                drawn_near(&frame, inside, RAY_COLOR).is_err(),
                "{camera:?}: a sampled ray is drawn on past its hit, at {inside:?}. {}",
                sampled_rays()
            );
        }
    }
}

#[test]
fn a_sampled_ray_that_hits_nothing_runs_on_in_sky_blue() {
    let frame = frame_of(&scene_of(vec![], v3(0.0, 5.0, 2.0)), &Camera::default());
    // The middle row's first ray leaves along about (-1, 0, -1).
    let direction = sampled_directions(&Camera::default())[0].normalize();
    for t in [2.0, 4.0, 6.0, 8.0] {
        let point = direction * t;
        if let Err(seen) = drawn_near(&frame, point, MISS_COLOR) {
            panic!(
                "no MISS_COLOR on the first sampled ray, which sees the sky, at {point:?}: {seen}. \
                 {}",
                sampled_rays()
            );
        }
    }
}

#[test]
fn every_tenth_ray_is_drawn_and_none_between() {
    // With nothing in the scene, each sampled ray is drawn, and halfway between two neighbours
    // (10 columns apart) the map is empty. At t = 6 they are 4.7 to 9.4 map pixels apart.
    let camera = Camera::default();
    let frame = frame_of(&scene_of(vec![], v3(0.0, 5.0, 2.0)), &camera);
    let t = 6.0;
    for pair in sampled_directions(&camera).windows(2) {
        let left = pair[0].normalize();
        let right = pair[1].normalize();
        let between = (left + right).normalize() * t;
        if !inside_map(between, 0.1) {
            // (0.1 units inside the map, so that the pixel looked at is on it)
            continue;
        }
        let seen = map_pixel(&frame, between);
        assert!(
            seen == BACKGROUND,
            "halfway between two sampled rays, at {between:?}, the map shows {}: a ray drawn \
             there. {}",
            named(&[seen]),
            holds(&[SAMPLED_FIGURE])
        );
        if let Err(seen) = drawn_near(&frame, left * t, MISS_COLOR) {
            panic!(
                "no sampled ray at {:?}: {seen}. {}",
                left * t,
                holds(&[SAMPLED_FIGURE])
            );
        }
    }
}

/// The leftmost point where a sampled ray hits the sphere, by the test's geometry.
fn leftmost_hit(camera: &Camera, center: V3, radius: f64) -> V3 {
    sampled_directions(camera)
        .into_iter()
        .filter_map(|d| ray_sphere(eye(camera), d, center, radius))
        .min_by(|a, b| a.x.total_cmp(&b.x))
        .expect("the test's set-up: a sampled ray hits the sphere")
}

#[test]
fn a_shadow_ray_runs_from_a_hit_to_the_light_and_stops_there() {
    // A ball ahead, the light to its left: the leftmost sampled hit's shadow ray runs to the
    // light, drawn in SHADOW_COLOR half way, and not on past the light.
    let camera = Camera::default();
    let center = v3(1.5, 0.0, -6.0);
    let radius = 1.0;
    let light = v3(-3.0, 0.0, -3.0);
    let frame = frame_of(
        &scene_of(vec![sphere(center, radius, matte(RED))], light),
        &camera,
    );
    let hit = leftmost_hit(&camera, center, radius);
    let halfway = hit + (light - hit) * 0.5;
    if let Err(seen) = drawn_near(&frame, halfway, SHADOW_COLOR) {
        panic!(
            "no SHADOW_COLOR half way from a sampled ray's hit at {hit:?} to the light: {seen}. \
             {}",
            sampled_rays()
        );
    }
    let past = light + (light - hit).normalize() * 0.5; // past the light's marker
    assert!(
        drawn_near(&frame, past, SHADOW_COLOR).is_err(),
        "the shadow ray is drawn on past the light, at {past:?}"
    );
}

#[test]
fn a_blocked_shadow_ray_ends_at_what_blocks_it() {
    let camera = Camera::default();
    let target = v3(1.5, 0.0, -6.0);
    let radius = 1.0;
    let light = v3(-3.0, 0.0, -3.0);
    let hit = leftmost_hit(&camera, target, radius);
    let to_light = (light - hit).normalize();
    // A small ball half way along the shadow ray blocks it.
    let blocker = hit + (light - hit) * 0.5;
    let objects = vec![
        sphere(target, radius, matte(RED)),
        sphere(blocker, 0.3, matte(RED)),
    ];
    let frame = frame_of(&scene_of(objects, light), &camera);
    let before = blocker - to_light * 0.45; // 0.15 before the blocker's surface
    let after = blocker + to_light * 0.7; // 0.4 past it, on the light's side
    if let Err(seen) = drawn_near(&frame, before, BLOCKED_COLOR) {
        panic!(
            "no BLOCKED_COLOR on the shadow ray before the ball that blocks it, at {before:?}: \
             {seen}. {}",
            sampled_rays()
        );
    }
    assert!(
        drawn_near(&frame, after, BLOCKED_COLOR).is_err(),
        "the blocked shadow ray is drawn on past the ball that blocks it, at {after:?}"
    );
}

#[test]
fn a_mirror_ray_leaves_each_sampled_hit_on_a_mirror_along_r() {
    // A mirror ball ahead, the light straight above its centre: the slice's hits face sideways,
    // away from it, so no shadow ray is drawn. From each sampled ray's hit its mirror ray
    // R = D - 2(D.N)N runs on, drawn at the first point along R, from 0.3 units on, that no
    // sampled ray is drawn over (they are drawn on top: a ray that hits the ball head on comes
    // back along itself).
    let camera = Camera::default();
    let center = v3(0.5, 0.0, -5.0);
    let scene = scene_of(
        vec![sphere(center, 1.0, mirror(WHITE, 0.9))],
        center + v3(0.0, 20.0, 0.0),
    );
    let frame = frame_of(&scene, &camera);
    let sampled: Vec<(V3, Option<V3>)> = sampled_directions(&camera)
        .into_iter()
        .map(|d| (d.normalize(), ray_sphere(eye(&camera), d, center, 1.0)))
        .collect();
    // Is a point within 2 map pixels of a sampled ray, from t = d (at or before the screen) to its
    // hit?
    let under_a_sampled_ray = |point: V3| {
        sampled.iter().any(|&(d, hit)| {
            let end = hit.map_or(f64::INFINITY, |hit| hit.length());
            let t = point.dot(d).clamp(README_SCREEN_DISTANCE, end);
            (point - d * t).length() < 2.0 / MAP_SCALE
        })
    };
    for &(d, hit_or_miss) in &sampled {
        let Some(hit) = hit_or_miss else {
            continue;
        };
        let n = hit - center;
        let r = d - n * (2.0 * d.dot(n));
        let along = (3..100)
            .map(|tenths| hit + r * (f64::from(tenths) / 10.0))
            .find(|&point| !under_a_sampled_ray(point))
            .expect("the test is wrong: a mirror ray stays under the sampled rays for 10 units");
        if let Err(seen) = drawn_near(&frame, along, MIRROR_COLOR) {
            panic!(
                "no MIRROR_COLOR at {along:?} on the mirror ray R = D - 2(D.N)N from the hit at \
                 {hit:?}: {seen}. Is R worked out as the slide does? {}",
                sampled_rays()
            );
        }
    }
}

#[test]
fn no_mirror_ray_leaves_a_matte_ball() {
    let scene = scene_of(
        vec![sphere(v3(0.5, 0.0, -5.0), 1.0, matte(RED))],
        v3(0.0, 20.0, 0.0),
    );
    let frame = frame_of(&scene, &Camera::default());
    assert!(
        !map_of(&frame).contains(&MIRROR_COLOR),
        "the map shows MIRROR_COLOR, yet the only ball is matte"
    );
}

#[test]
fn the_sampled_rays_start_at_the_screen() {
    // Between the eye's marker and the screen no sampled ray is drawn, so that both stand clear;
    // just past the screen each is.
    let scene = scene_of(vec![], v3(0.0, 5.0, 2.0));
    for camera in two_poses() {
        let frame = frame_of(&scene, &camera);
        let (view, ..) = camera_axes(&camera);
        for direction in sampled_directions(&camera) {
            let unit = direction.normalize();
            let screen = README_SCREEN_DISTANCE / unit.dot(view); // where it meets the screen: t = d / D.V
            let pixel = 1.0 / (unit.x.hypot(unit.z) * MAP_SCALE); // t for a map pixel along it
            let at = |t: f64| eye(&camera) + unit * t;
            // From past the eye's marker to 6 map pixels before the screen's row (the rays beside
            // it cross the row at 45 degrees at most), every quarter map pixel.
            let mut t = 4.0 * pixel;
            while t < screen - 6.0 * pixel {
                assert!(
                    drawn_near(&frame, at(t), MISS_COLOR).is_err(),
                    "{camera:?}: a sampled ray is drawn at t = {t:.2}, before the screen at \
                     t = {screen:.2}. {}",
                    holds(&[SCREEN_FIGURE])
                );
                t += 0.25 * pixel;
            }
            if let Err(seen) = drawn_near(&frame, at(screen + 3.0 * pixel), MISS_COLOR) {
                panic!(
                    "{camera:?}: no sampled ray 3 map pixels past the screen: {seen}. {}",
                    holds(&[SCREEN_FIGURE])
                );
            }
        }
    }
}

#[test]
fn the_sampled_rays_are_drawn_over_the_shadow_and_mirror_rays() {
    // A mirror ball and matte balls ahead, the light behind and above: many shadow and mirror
    // rays cross the sampled ones. Along each sampled ray, up to 2 map pixels before its hit,
    // under MOST_COVERED of the points show another colour than the ray's (black between its dots
    // is allowed), and over LEAST_ON_RAY its own. Measured at 56 VIEWs from 96 to 1100: at most
    // 2.1% covered and at least 83% on the ray; with the sampled rays drawn first, 4.9% to 12%
    // covered.
    const MOST_COVERED: f64 = 0.035;
    const LEAST_ON_RAY: f64 = 0.75;
    let camera = Camera::default();
    let balls = [
        (v3(0.3, 0.0, -4.5), 1.0, mirror(WHITE, 0.85)),
        (v3(-2.0, -0.2, -4.2), 0.8, matte(RED)),
        (v3(1.9, -0.4, -3.4), 0.6, matte(PURE_GREEN)),
    ];
    let objects = balls.iter().map(|&(c, r, m)| sphere(c, r, m)).collect();
    let frame = frame_of(&scene_of(objects, v3(-3.0, 5.0, 1.0)), &camera);
    let mut on_ray = 0;
    let mut covered = 0;
    let mut checked = 0;
    for direction in sampled_directions(&camera) {
        let d = direction.normalize();
        let hit = balls
            .iter()
            .filter_map(|&(center, radius, _)| ray_sphere(eye(&camera), d, center, radius))
            .map(|point| point.length())
            .min_by(f64::total_cmp);
        let color = if hit.is_some() { RAY_COLOR } else { MISS_COLOR };
        let end = hit.map_or(f64::INFINITY, |t| t - 2.0 / MAP_SCALE);
        let mut t = 1.5; // past the screen's row, 1 to √2 ahead
        while t < end && inside_map(d * t, 0.0) {
            let pixel = map_pixel(&frame, d * t);
            checked += 1;
            if pixel == color {
                on_ray += 1;
            } else if pixel != BACKGROUND {
                covered += 1;
            }
            t += 0.5 / MAP_SCALE; // every half map pixel
        }
    }
    let share = |count: i32| f64::from(count) / f64::from(checked);
    assert!(
        share(covered) < MOST_COVERED,
        "{covered} of {checked} points along the sampled rays show another ray's colour on top, \
         over {MOST_COVERED} of them"
    );
    assert!(
        share(on_ray) > LEAST_ON_RAY,
        "only {on_ray} of {checked} points along the sampled rays show their colour, expected \
         over {LEAST_ON_RAY} of them"
    );
}

#[test]
fn with_a_level_camera_the_slice_never_meets_the_floor() {
    // (compares) The rays of a level camera's middle row are level: they never meet a floor
    // below the eye, so a floor changes nothing on the map. Poses around the demo, the last one
    // where rounding once tilted the row into the floor 10^16 units away.
    let light = v3(0.0, 5.0, 0.0);
    for (position, yaw) in [
        (v3(0.0, 0.0, 0.0), 0.0),
        (v3(0.7, 0.3, -1.0), 0.4),
        (v3(-1.0, 2.5, 1.0), -2.0),
        (v3(2.0, 0.1, 2.0), 4.0),
        (v3(-1.9, 0.18, 0.07), 0.03),
    ] {
        let camera = camera_at(position, yaw, 0.0);
        let empty = frame_of(&scene_of(vec![], light), &camera);
        let floor_only = frame_of(&scene_of(vec![checkered_floor()], light), &camera);
        assert!(
            map_of(&empty) == map_of(&floor_only),
            "{camera:?}: the floor changes the map, so a level camera's sampled rays, which \
             never come down to the floor, are drawn meeting it far off (yellow, a hit, where \
             they should be sky blue, a miss). That is what happens when the screen is worked out \
             in the world (C = E + dV, then D = p(u, v) - E): rounding there tilts the level row \
             down. Keep C, p0, p1 and p2 relative to the eye (C = dV, D = p(u, v)), as \
             primary_ray does, and E only as the ray's origin."
        );
    }
}

#[test]
fn from_far_off_the_map_the_sampled_rays_still_cross_it() {
    // The eye at z = 20 to 40, 17 to 37 units behind the map's bottom edge, a big ball ahead on the
    // map: the sampled rays come in over the map's bottom edge and run up to the ball, or, missing
    // it, across the map to its top edge. They are looked at `INSET` inside the map's edges, clear
    // of the eye's marker there (7 map pixels wide), and `BEFORE` units before a hit's depth. (Of
    // the rays that cross the map, from the three distances together, 14 hit the ball and 10 miss
    // it.)
    const INSET: f64 = 16.0 / MAP_SCALE; // 16 map pixels
    const BEFORE: f64 = 0.3;
    let center = v3(0.0, 0.0, -5.0);
    let radius = 3.0;
    let scene = scene_of(
        vec![sphere(center, radius, matte(RED))],
        v3(0.0, 20.0, -5.0),
    );
    let bottom = MAP_CORNER.z + MAP_SIDE - INSET;
    let top = MAP_CORNER.z + INSET;
    let within_width =
        |point: V3| point.x > MAP_CORNER.x + INSET && point.x < MAP_CORNER.x + MAP_SIDE - INSET;
    for distance in [20.0, 30.0, 40.0] {
        let camera = camera_at(v3(0.0, 0.0, distance), 0.0, 0.0);
        let frame = frame_of(&scene, &camera);
        for direction in sampled_directions(&camera) {
            let d = direction.normalize();
            let at_z = |z: f64| eye(&camera) + d * ((z - distance) / d.z);
            if !within_width(at_z(bottom)) {
                continue; // it passes beside the map
            }
            let (color, end) = match ray_sphere(eye(&camera), direction, center, radius) {
                Some(hit) => (RAY_COLOR, hit.z + BEFORE),
                None if within_width(at_z(top)) => (MISS_COLOR, top),
                None => continue, // it leaves the map by a side
            };
            for point in [at_z(bottom), at_z((bottom + end) / 2.0), at_z(end)] {
                if let Err(seen) = drawn_near(&frame, point, color) {
                    panic!(
                        "the eye {distance} units out: its sampled ray is missing at {point:?}, \
                         {seen}. {}",
                        sampled_rays()
                    );
                }
            }
        }
    }
}

#[test]
fn every_point_of_a_huge_spheres_circle_has_its_outline_within_a_pixel() {
    // A ball of radius 35 cut through its centre, the eye looking away from it, the light off
    // the map: every point of the circle 0.1 units or more inside the map has the outline within
    // a map pixel of it.
    let center = v3(0.0, 0.0, -40.0);
    let radius = 35.0;
    let scene = scene_of(
        vec![sphere(center, radius, matte(PURE_RED))],
        v3(0.0, 100.0, 100.0),
    );
    let frame = frame_of(
        &scene,
        &camera_at(v3(0.0, 0.0, 0.0), std::f64::consts::PI, 0.0),
    );
    let points = 20_000; // every 0.011 units along the circle
    for i in 0..points {
        let angle = std::f64::consts::TAU * f64::from(i) / f64::from(points);
        let on_circle = center + v3(angle.cos(), 0.0, angle.sin()) * radius;
        if !inside_map(on_circle, 0.1) {
            continue;
        }
        if let Err(seen) = drawn_near(&frame, on_circle, pixel_of(PURE_RED)) {
            panic!("the outline of a ball of radius 35 is off its circle at {on_circle:?}: {seen}");
        }
    }
}

#[test]
fn the_legend_colours_are_told_apart_by_every_eye() {
    for (i, &(name_a, a)) in LEGEND.iter().enumerate() {
        for &(name_b, b) in &LEGEND[..i] {
            if let Some(problem) = vision::too_alike(a, b) {
                panic!("{name_a} and {name_b} are too alike: {problem}");
            }
        }
    }
    if let Some(problem) = vision::same_hue(RAY_COLOR, MISS_COLOR) {
        panic!("a sampled ray's hit and miss colours, RAY_COLOR and MISS_COLOR: {problem}");
    }
}
