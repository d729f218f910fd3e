// A Whitted-style ray tracer in one file; beside its 3D view, a top-down 2D slice of the scene.
use minifb::{Key, ScaleMode, Window, WindowOptions};
use std::f64::consts::{FRAC_PI_2, TAU};
use std::ops::{Add, Mul, Sub};
use std::time::Instant;

const VIEW: usize = 512; // each half of the window is VIEW x VIEW pixels
const WIDTH: usize = 2 * VIEW; // a row of the frame: the 3D view, then the 2D slice

// Vector math: points, directions and colours (x, y, z = red, green, blue) are all a Vec3.
#[derive(Clone, Copy, Default, PartialEq)]
struct Vec3 {
    x: f64,
    y: f64,
    z: f64,
}

const fn vec3(x: f64, y: f64, z: f64) -> Vec3 {
    Vec3 { x, y, z }
}

impl Vec3 {
    fn dot(self, other: Vec3) -> f64 {
        self.x * other.x + self.y * other.y + self.z * other.z
    }
    fn length(self) -> f64 {
        self.dot(self).sqrt()
    }
    fn normalize(self) -> Vec3 {
        self * (1.0 / self.length()) // v / |v|
    }
}

impl Add for Vec3 {
    type Output = Vec3;
    fn add(self, other: Vec3) -> Vec3 {
        vec3(self.x + other.x, self.y + other.y, self.z + other.z)
    }
}

impl Sub for Vec3 {
    type Output = Vec3;
    fn sub(self, other: Vec3) -> Vec3 {
        vec3(self.x - other.x, self.y - other.y, self.z - other.z)
    }
}

impl Mul<f64> for Vec3 {
    type Output = Vec3;
    fn mul(self, scale: f64) -> Vec3 {
        vec3(self.x * scale, self.y * scale, self.z * scale)
    }
}

// Step 2, the ray: p(t) = O + tD with D normalized and 0 < t < ray.t, the distance it reaches.
struct Ray {
    origin: Vec3,
    direction: Vec3,
    t: f64,
}

impl Ray {
    fn new(origin: Vec3, direction: Vec3, t: f64) -> Ray {
        Ray {
            origin,
            direction: direction.normalize(), // D normalized: t is then the distance along the ray
            t,
        }
    }
}

// Steps 1 and 4, the camera: eye E looking along V at a screen centred on C = E + dV, corners p0
// bottom left, p1 bottom right, p2 top left; a ray through p(u, v) = p0 + u(p1 - p0) + v(p2 - p0).
const SCREEN_DISTANCE: f64 = 1.0; // the slide's d: a screen 2 wide at distance 1 sees 90 degrees

#[derive(Clone, Copy, Default, PartialEq)] // by default at (0, 0, 0) looking at (0, 0, -1)
struct Camera {
    position: Vec3,
    yaw: f64,   // radians about +y; positive turns the view left
    pitch: f64, // radians; positive looks up
}

/// The unit direction `yaw` radians left of -z about +y and `pitch` radians up from level.
fn heading(yaw: f64, pitch: f64) -> Vec3 {
    let level = pitch.cos(); // cos pitch scales the part of the heading that lies level
    vec3(-yaw.sin() * level, pitch.sin(), -yaw.cos() * level)
}

impl Camera {
    /// V, right and up: the slide's camera matrix [right | up | -V] turns -z, x and y into them.
    fn axes(&self) -> (Vec3, Vec3, Vec3) {
        (
            heading(self.yaw, self.pitch),
            heading(self.yaw - FRAC_PI_2, 0.0), // a quarter turn right, level
            heading(self.yaw, self.pitch + FRAC_PI_2), // a quarter turn up
        )
    }
    /// Step 4: the primary ray through (x, y), in pixels from the screen's top left, from O = E.
    fn primary_ray(&self, x: f64, y: f64) -> Ray {
        let (forward, right, up) = self.axes(); // V, right, up
        // C, p0, p1, p2 relative to E: in the world, rounding would tilt a level row to the floor.
        let center = forward * SCREEN_DISTANCE;
        let p0 = center - right - up; // the slide's C + (-1, -1, 0), turned by the camera matrix
        let p1 = center + right - up;
        let p2 = center - right + up;
        let u = x / VIEW as f64;
        let v = 1.0 - y / VIEW as f64;
        let direction = p0 + (p1 - p0) * u + (p2 - p0) * v; // p(u, v) - E
        Ray::new(self.position, direction, f64::INFINITY)
    }
}

// Step 3, the slide's Primitive class and its subclasses Sphere and Plane: an enum and its variants.
enum Primitive {
    Sphere { center: Vec3, radius: f64 }, // (p - C).(p - C) = r²
    Plane { normal: Vec3, offset: f64 },  // p.N + d = 0, N normalized, d = offset
}

impl Primitive {
    /// Step 5: the distance t of the ray's first hit with 0 < t < ray.t, if any.
    fn intersect(&self, ray: &Ray) -> Option<f64> {
        let ahead = |t| (t > 0.0 && t < ray.t).then_some(t);
        match *self {
            // t = -(O.N + d) / (D.N); a ray parallel to the plane (D.N = 0) misses it.
            Primitive::Plane { normal, offset } => {
                let slant = ray.direction.dot(normal);
                if slant == 0.0 {
                    return None;
                }
                ahead(-(ray.origin.dot(normal) + offset) / slant)
            }
            // The slide's test: c = C - O, t = c.D, p² = q.q, q = c - tD, a hit at t - √(r² - p²);
            // from inside (the camera may walk in) at t + √(r² - p²), which the slide leaves out.
            Primitive::Sphere { center, radius } => {
                let c = center - ray.origin;
                let t = c.dot(ray.direction);
                let p2 = c.dot(c) - t * t; // q.q, as |c|² = t² + |q|² (Pythagoras; D is unit)
                if p2 > radius * radius {
                    return None;
                }
                let half_chord = (radius * radius - p2).sqrt();
                ahead(t - half_chord).or(ahead(t + half_chord))
            }
        }
    }
}

// The scene: the objects, each with its material, one point light and a flat sky.
#[derive(Clone, Copy)]
struct Material {
    color: Vec3,
    reflectivity: f64, // 0 is matte, 1 a perfect mirror
    checkered: bool,   // a checkerboard of unit squares in x and z, as on the floor
}

struct Scene {
    objects: Vec<(Primitive, Material)>,
    light: Vec3,
    sky: Vec3,
}

impl Scene {
    /// The demo: four balls (centre, radius, colour, reflectivity) on a checkered floor, one light.
    fn demo() -> Scene {
        let white = vec3(0.9, 0.9, 0.9);
        let balls = [
            (vec3(0.3, 0.0, -4.5), 1.0, white, 0.85), // a mirror
            (vec3(-2.0, -0.2, -4.2), 0.8, vec3(0.9, 0.2, 0.2), 0.0), // red
            (vec3(1.9, -0.4, -3.4), 0.6, vec3(0.2, 0.8, 0.3), 0.0), // green
            (vec3(-0.9, -0.45, -2.6), 0.55, vec3(0.2, 0.4, 0.9), 0.0), // blue
        ];
        let floor = Primitive::Plane {
            normal: vec3(0.0, 1.0, 0.0),
            offset: 1.0, // p.N + d = y + 1 = 0: the floor is y = -1
        };
        let checkered_white = Material {
            color: white,
            reflectivity: 0.0,
            checkered: true,
        };
        let mut objects = vec![(floor, checkered_white)];
        for (center, radius, color, reflectivity) in balls {
            let material = Material {
                color,
                reflectivity,
                checkered: false,
            };
            objects.push((Primitive::Sphere { center, radius }, material));
        }
        Scene {
            objects,
            light: vec3(-3.0, 5.0, 1.0),
            sky: vec3(0.5, 0.7, 1.0),
        }
    }
}

// Steps 8 and 9, shading: colour = surface × (ambient + (1 - ambient) N.L if the shadow ray reaches
// the light) × ODD_SQUARE_BRIGHTNESS on an odd square, mixed by reflectivity with what R sees.
const AMBIENT: f64 = 0.1; // the share of the light a surface gets even in shadow
const MAX_DEPTH: u32 = 5; // mirror bounces followed at most
const LIFT: f64 = 1e-4; // a ray leaving a surface starts this far off it
const ODD_SQUARE_BRIGHTNESS: f64 = 0.25; // odd squares are this bright beside the even ones

struct Hit {
    point: Vec3,  // where a ray hits
    normal: Vec3, // unit, on the side the ray comes from
    material: Material,
}

impl Hit {
    /// A ray leaving the hit, LIFT off its surface along N: from P itself, rounded to just under
    /// the surface, it would hit that surface at once and speckle it with false shadow (acne).
    fn outgoing(&self, direction: Vec3, t: f64) -> Ray {
        Ray::new(self.point + self.normal * LIFT, direction, t)
    }
    /// The mirror ray of a ray along D: R = D - 2(D.N)N.
    fn mirror_ray(&self, direction: Vec3) -> Ray {
        let mirrored = direction - self.normal * 2.0 * direction.dot(self.normal);
        self.outgoing(mirrored, f64::INFINITY)
    }
}

impl Scene {
    /// Step 6, the nearest intersection: each object that the ray hits before ray.t shortens it.
    fn nearest_hit(&self, ray: &mut Ray) -> Option<Hit> {
        let mut nearest = None;
        for (primitive, material) in &self.objects {
            if let Some(t) = primitive.intersect(ray) {
                ray.t = t;
                nearest = Some((primitive, *material));
            }
        }
        let (primitive, material) = nearest?;
        let point = ray.origin + ray.direction * ray.t; // P = O + tD
        let outward = match *primitive {
            Primitive::Sphere { center, .. } => (point - center).normalize(),
            Primitive::Plane { normal, .. } => normal,
        };
        // N turned to face the ray: a ball seen from inside, the floor from below, lit on our side.
        let facing = outward.dot(ray.direction) < 0.0;
        let normal = if facing { outward } else { outward * -1.0 };
        Some(Hit {
            point,
            normal,
            material,
        })
    }

    /// The shadow ray from a hit to the light; none where N.L <= 0, the light behind it or on it.
    fn shadow_ray(&self, hit: &Hit) -> Option<Ray> {
        let to_light = self.light - hit.point;
        (to_light.dot(hit.normal) > 0.0).then(|| hit.outgoing(to_light, to_light.length()))
    }

    /// Step 9: the colour a ray brings back, `depth` mirror bounces deep; the sky if it hits none.
    fn trace(&self, mut ray: Ray, depth: u32) -> Vec3 {
        let Some(hit) = self.nearest_hit(&mut ray) else {
            return self.sky;
        };
        let mut brightness = AMBIENT;
        if let Some(mut shadow) = self.shadow_ray(&hit)
            && self.nearest_hit(&mut shadow).is_none()
        {
            brightness += (1.0 - AMBIENT) * shadow.direction.dot(hit.normal); // L is shadow's D
        }
        if hit.material.checkered && odd_square(hit.point) {
            brightness *= ODD_SQUARE_BRIGHTNESS;
        }
        let color = hit.material.color * brightness;
        let reflectivity = hit.material.reflectivity;
        if reflectivity <= 0.0 || depth >= MAX_DEPTH {
            return color; // the recursion must end: at MAX_DEPTH even a mirror shows its own colour
        }
        color * (1.0 - reflectivity)
            + self.trace(hit.mirror_ray(ray.direction), depth + 1) * reflectivity
    }
}

/// Step 8, the slide's checkerboard F = ((int)(2 λ1) + (int)λ2) & 1, λ1 = x, λ2 = z, with no 2 (it
/// would halve the squares in x) and floor for (int) (truncating merges the squares beside 0).
fn odd_square(point: Vec3) -> bool {
    ((point.x.floor() as i64 + point.z.floor() as i64) & 1) == 1
}

// Rendering, the slide's step 6: each pixel of the 3D view its primary ray's colour; then the map.
fn render(scene: &Scene, camera: &Camera, frame: &mut [u32]) {
    for y in 0..VIEW {
        for x in 0..VIEW {
            let ray = camera.primary_ray(x as f64 + 0.5, y as f64 + 0.5); // the pixel's centre
            frame[y * WIDTH + x] = to_rgb(scene.trace(ray, 0));
        }
    }
    draw_slice(scene, camera, frame);
}

fn to_rgb(color: Vec3) -> u32 {
    let byte = |channel: f64| (channel.min(1.0) * 255.0) as u32; // brighter than white shows 255
    byte(color.x) << 16 | byte(color.y) << 8 | byte(color.z)
}

// The 2D slice, the assignment's "for y = 0, visualize every 10th ray", seen from above (x right,
// -z up): the plane of the screen's middle row, y = 0 at the start, tilting so its rays stay in it.
const MAP_SIDE: f64 = 12.8; // the map shows the same square of the world at any VIEW, this wide
const EYE_OVER_EDGE: f64 = 3.4; // the start eye this far over its bottom edge: the demo fits above
const MAP_CORNER: Vec3 = vec3(-MAP_SIDE / 2.0, 0.0, EYE_OVER_EDGE - MAP_SIDE); // its top left x, z
const MAP_SCALE: f64 = VIEW as f64 / MAP_SIDE; // map pixels per world unit
const SAMPLED_EVERY: usize = 10; // the assignment's "every 10th ray"
const DOT_RADIUS: i32 = 1; // a hit's dot is 3 x 3 map pixels: 1 either side of its point
const MARKER_RADIUS: i32 = 3; // the light and the eye are 7 x 7
// Colours no two alike, also to red-green colour-blind eyes, the most important the brightest.
const BACKGROUND: u32 = 0x000000; // black
const CAMERA_COLOR: u32 = 0xff20c0; // pink: the eye and the screen's middle row
const RAY_COLOR: u32 = 0xffff00; // yellow: a sampled ray, from the screen to its hit
const MISS_COLOR: u32 = 0x80a0ff; // sky blue: a sampled ray that sees the sky
const LIGHT_COLOR: u32 = 0xff8000; // orange: the light
const SHADOW_COLOR: u32 = 0x802000; // rust: a shadow ray that reaches the light
const BLOCKED_COLOR: u32 = 0x6040a0; // violet: a shadow ray up to what blocks it, a dot there
const MIRROR_COLOR: u32 = 0x008080; // teal: a mirror ray to its hit, a dot there, or the edge

/// Colours the map pixels up to `radius` pixels either side of a world point, those on the map.
fn plot(frame: &mut [u32], point: Vec3, radius: i32, color: u32) {
    let on_map = 0.0..VIEW as f64;
    let middle = (point - MAP_CORNER) * MAP_SCALE; // the point in map pixels
    for dx in -radius..=radius {
        for dz in -radius..=radius {
            let pixel = middle + vec3(dx as f64, 0.0, dz as f64);
            if on_map.contains(&pixel.x) && on_map.contains(&pixel.z) {
                frame[pixel.z as usize * WIDTH + VIEW + pixel.x as usize] = color;
            }
        }
    }
}

/// Draws p(t), from <= t <= ray.t, a dot every map pixel, clipped to the map by the slab method:
/// in x, then in z, p(t) is over the map between the t where it crosses one edge and the other.
fn draw_ray(frame: &mut [u32], ray: &Ray, from: f64, color: u32) {
    let o_on_map = (ray.origin - MAP_CORNER) * MAP_SCALE; // O and D in map pixels, not world units
    let d_on_map = ray.direction * MAP_SCALE;
    let mut enter = from;
    let mut leave = ray.t;
    for (o, d) in [(o_on_map.x, d_on_map.x), (o_on_map.z, d_on_map.z)] {
        if d == 0.0 {
            continue; // it runs along these edges, never across; plot leaves out what is off them
        }
        let at_0 = -o / d; // t = (edge - O) / D at the edge 0,
        let at_view = (VIEW as f64 - o) / d; // and at the edge VIEW
        enter = enter.max(at_0.min(at_view)); // from an eye off the map: from where it reaches it
        leave = leave.min(at_0.max(at_view));
    }
    let pixels_per_t = d_on_map.x.hypot(d_on_map.z); // along the map
    if enter >= leave || pixels_per_t == 0.0 {
        return; // it misses the map, or runs straight up or down: no length on the map
    }
    let dots = ((leave - enter) * pixels_per_t).floor() as usize;
    for dot in 0..=dots {
        let t = enter + dot as f64 / pixels_per_t;
        plot(frame, ray.origin + ray.direction * t, 0, color);
    }
}

/// Draws a ray from t = `from` to its nearest hit and a dot there, or all of it, in those colours.
fn follow(frame: &mut [u32], scene: &Scene, mut ray: Ray, from: f64, on_hit: u32, on_miss: u32) {
    let Some(hit) = scene.nearest_hit(&mut ray) else {
        draw_ray(frame, &ray, from, on_miss);
        return;
    };
    draw_ray(frame, &ray, from, on_hit);
    plot(frame, hit.point, DOT_RADIUS, on_hit);
}

/// The map back to front, the key things on top: outlines, shadow and mirror rays, rays, markers.
fn draw_slice(scene: &Scene, camera: &Camera, frame: &mut [u32]) {
    for row in frame.chunks_mut(WIDTH) {
        row[VIEW..].fill(BACKGROUND);
    }
    let (forward, right, up) = camera.axes(); // the slice holds V and right; up is its normal
    for (primitive, material) in &scene.objects {
        match *primitive {
            // The slice cuts a sphere in a circle around C - hN, radius √(r² - h²), h = (C - E).N.
            Primitive::Sphere { center, radius } => {
                let height = (center - camera.position).dot(up);
                if height.abs() >= radius {
                    continue;
                }
                let circle_radius = (radius * radius - height * height).sqrt();
                let dots = (TAU * circle_radius * MAP_SCALE).ceil() as usize; // a dot a map pixel
                for dot in 0..dots {
                    let angle = TAU * dot as f64 / dots as f64;
                    let on_circle = center - up * height
                        + (right * angle.cos() + forward * angle.sin()) * circle_radius;
                    plot(frame, on_circle, 0, to_rgb(material.color));
                }
            }
            Primitive::Plane { .. } => {} // not drawn: its line would bury the rays' dots on it
        }
    }
    // Through v = 0.5, between the two middle pixel rows: in the start pose, the slide's "y = 0".
    let sampled = || {
        (0..VIEW)
            .step_by(SAMPLED_EVERY)
            .map(|x| camera.primary_ray(x as f64 + 0.5, VIEW as f64 / 2.0)) // column centres
    };
    for mut ray in sampled() {
        let Some(hit) = scene.nearest_hit(&mut ray) else {
            continue;
        };
        if let Some(shadow) = scene.shadow_ray(&hit) {
            follow(frame, scene, shadow, 0.0, BLOCKED_COLOR, SHADOW_COLOR);
        }
        if hit.material.reflectivity > 0.0 {
            let mirror = hit.mirror_ray(ray.direction);
            follow(frame, scene, mirror, 0.0, MIRROR_COLOR, MIRROR_COLOR);
        }
    }
    // From the screen on, t = d / D.V: before it the rays would bury the eye and the screen.
    for ray in sampled() {
        let at_screen = SCREEN_DISTANCE / ray.direction.dot(forward);
        follow(frame, scene, ray, at_screen, RAY_COLOR, MISS_COLOR);
    }
    let row_start = camera.position + forward * SCREEN_DISTANCE - right; // the row from C - right
    draw_ray(frame, &Ray::new(row_start, right, 2.0), 0.0, CAMERA_COLOR); // to C + right
    // The light's marker, then the eye's; off the map, each whole on the edge nearest to it.
    let inset = (MARKER_RADIUS as f64 + 0.5) / MAP_SCALE; // its square's half width: all on the map
    let fit = |value: f64, corner: f64| value.clamp(corner + inset, corner + MAP_SIDE - inset);
    for (point, color) in [(scene.light, LIGHT_COLOR), (camera.position, CAMERA_COLOR)] {
        let middle = vec3(fit(point.x, MAP_CORNER.x), 0.0, fit(point.z, MAP_CORNER.z));
        plot(frame, middle, MARKER_RADIUS, color);
    }
}

// Step 7, the controls: a step reads the keys and moves the camera; a new pose or size is rendered.
const MOVE_SPEED: f64 = 2.0; // units a second along each held key's direction
const TURN_SPEED: f64 = 1.5; // radians a second

/// The camera `dt` seconds on with `keys` down, each pair of keys an axis; Home: back to the start.
fn moved(mut camera: Camera, keys: &[Key], dt: f64) -> Camera {
    if keys.contains(&Key::Home) {
        return Camera::default();
    }
    let down = |key| if keys.contains(&key) { 1.0 } else { 0.0 };
    let axis = |plus, minus| down(plus) - down(minus); // 1, -1, or 0 with both or neither down
    let (forward, right, _) = camera.axes();
    let motion = forward * axis(Key::W, Key::S)
        + right * axis(Key::D, Key::A)
        + vec3(0.0, axis(Key::R, Key::F), 0.0);
    camera.position = camera.position + motion * MOVE_SPEED * dt;
    camera.yaw += TURN_SPEED * dt * axis(Key::Left, Key::Right);
    let tilted = camera.pitch + TURN_SPEED * dt * axis(Key::Up, Key::Down);
    camera.pitch = tilted.clamp(-FRAC_PI_2, FRAC_PI_2); // straight up or down at most
    camera
}

const STEPS_PER_SECOND: usize = 60; // a screen's rate: at rest each step mostly sleeps
const RESEND_EVERY: usize = STEPS_PER_SECOND / 2; // at rest a step in this many sends the frame

fn main() {
    let options = WindowOptions {
        resize: true, // the user may size the window: the frame is scaled to fit, 2:1 kept
        scale_mode: ScaleMode::AspectRatioStretch,
        ..WindowOptions::default()
    };
    let mut window = Window::new("raytracer", WIDTH, VIEW, options).unwrap_or_else(|error| {
        // No window, most often for want of an X server: one line on why, and exit status 1.
        let display = std::env::var("DISPLAY").unwrap_or_default();
        eprintln!("raytracer: {error}; DISPLAY is {display:?} (empty if not set); with no display, `cargo run --example frame` saves the frame as a PNG");
        std::process::exit(1)
    });
    window.set_target_fps(STEPS_PER_SECOND);
    let scene = Scene::demo();
    let mut camera = Camera::default();
    let mut frame = vec![BACKGROUND; WIDTH * VIEW];
    let mut rendered = None; // the pose shown and window size `frame` is drawn for, none at first
    let mut steps_at_rest = 0; // since a render; minifb never repaints an uncovered window: re-send
    let mut stale = Vec::new(); // keys held when the focus left: ignored until let go
    let mut last_step = Instant::now(); // the camera moves by speed × each step's time
    while window.is_open() && !window.is_key_down(Key::Escape) {
        let keys = keys_down(&window, &mut stale);
        camera = moved(camera, &keys, last_step.elapsed().as_secs_f64());
        last_step = Instant::now();
        // The title's pose, to 3 decimals, yaw within a turn: the frame command saves this frame.
        let Vec3 { x, y, z } = camera.position;
        let [x, y, z, yaw, pitch] =
            [x, y, z, camera.yaw % TAU, camera.pitch].map(|value| (value * 1e3).round() / 1e3);
        let shown = Camera {
            position: vec3(x, y, z),
            yaw,
            pitch,
        };
        let now = Some((shown, window.get_size())); // a resized window is black: redraw it
        if rendered != now {
            render(&scene, &shown, &mut frame);
            rendered = now;
            steps_at_rest = 0;
            window.set_title(&format!("raytracer - pose {x} {y} {z} {yaw} {pitch}"));
        }
        if steps_at_rest % RESEND_EVERY == 0 {
            let sent = window.update_with_buffer(&frame, WIDTH, VIEW);
            sent.expect("a frame the window's size");
        } else {
            window.update(); // at rest: reads the keys and paces the loop; nothing rendered or sent
        }
        steps_at_rest += 1;
    }
}

/// Keys down, less those held since the focus left (X never says they were let go): no drifting.
fn keys_down(window: &Window, stale: &mut Vec<Key>) -> Vec<Key> {
    let mut keys = window.get_keys();
    if !window.is_active() {
        *stale = keys.clone();
    }
    stale.retain(|key| keys.contains(key));
    keys.retain(|key| !stale.contains(key));
    keys
}
