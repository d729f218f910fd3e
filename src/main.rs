//! A Whitted-style ray tracer in one file: spheres and a checkered floor, one point light, hard
//! shadows and mirror reflections, and beside the 3D view a top-down 2D slice of the scene.
use minifb::{Key, Window, WindowOptions};
use std::f64::consts::{FRAC_PI_2, TAU};
use std::{io::Write, ops, sync::Mutex, time::Instant};

pub const VIEW: usize = 512; // each half of the window is VIEW x VIEW pixels
pub const WIDTH: usize = 2 * VIEW; // a row of the frame: the 3D view, then the 2D slice
pub const MAX_DEPTH: u32 = 5; // mirror bounces followed at most
pub const AMBIENT: f64 = 0.1; // the share of the light a surface gets even in shadow
const ODD_SQUARE: f64 = 0.25; // the share of the light the checkerboard's odd squares reflect
const SCREEN_DISTANCE: f64 = 1.0; // the slide's d: a screen 2 wide at distance 1 sees 90 degrees
const SELF_HIT: f64 = 1e-6; // a ray leaving a surface starts this far off it, times 1 + |point|

// Vector math: points, directions and colours (x, y, z = red, green, blue) are all a Vec3.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Vec3 {
    pub x: f64,
    pub y: f64,
    pub z: f64,
}

pub const fn vec3(x: f64, y: f64, z: f64) -> Vec3 {
    Vec3 { x, y, z }
}

impl Vec3 {
    pub fn dot(self, other: Vec3) -> f64 {
        self.x * other.x + self.y * other.y + self.z * other.z
    }
    pub fn length(self) -> f64 {
        self.dot(self).sqrt()
    }
    pub fn normalize(self) -> Vec3 {
        self * (1.0 / self.length())
    }
}

impl ops::Add for Vec3 {
    type Output = Vec3;
    fn add(self, other: Vec3) -> Vec3 {
        vec3(self.x + other.x, self.y + other.y, self.z + other.z)
    }
}

impl ops::Sub for Vec3 {
    type Output = Vec3;
    fn sub(self, other: Vec3) -> Vec3 {
        vec3(self.x - other.x, self.y - other.y, self.z - other.z)
    }
}

impl ops::Mul<f64> for Vec3 {
    type Output = Vec3;
    fn mul(self, scale: f64) -> Vec3 {
        vec3(self.x * scale, self.y * scale, self.z * scale)
    }
}

// The ray: p(t) = O + tD with D normalized and 0 < t < ray.t, the distance it reaches so far.
#[derive(Clone, Copy, Debug)]
pub struct Ray {
    pub origin: Vec3,
    pub direction: Vec3,
    pub t: f64,
}

impl Ray {
    /// The ray from `origin` along `direction` (of any length: it is normalized here), `t` long.
    pub fn new(origin: Vec3, direction: Vec3, t: f64) -> Ray {
        let direction = direction.normalize();
        Ray {
            origin,
            direction,
            t,
        }
    }
    /// A ray leaving a surface at `point`, on the side its `normal` faces. It starts lifted off
    /// the surface, further than the point's rounding error (which grows with its distance from 0),
    /// so that it does not hit that surface again.
    pub fn leaving(point: Vec3, normal: Vec3, direction: Vec3, t: f64) -> Ray {
        let lift = SELF_HIT * (1.0 + point.length());
        Ray::new(point + normal * lift, direction, t)
    }
    pub fn at(&self, t: f64) -> Vec3 {
        self.origin + self.direction * t
    }
}

// The camera: eye E looking along V at a screen centred on C = E + dV. Its corners are p0 bottom
// left, p1 bottom right and p2 top left; a ray goes through p(u, v) = p0 + u(p1 - p0) + v(p2 - p0).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Camera {
    pub position: Vec3,
    pub yaw: f64,   // radians about +y; positive turns the view left
    pub pitch: f64, // radians; positive looks up
}

impl Camera {
    /// The camera's rotation: its view direction V = (-sin yaw cos pitch, sin pitch, -cos yaw
    /// cos pitch), the screen's right (V turned a quarter about y, level) and up = right × V.
    pub fn axes(&self) -> [Vec3; 3] {
        let (sin_yaw, cos_yaw) = self.yaw.sin_cos();
        let (sin_pitch, cos_pitch) = self.pitch.sin_cos();
        let view = vec3(-sin_yaw * cos_pitch, sin_pitch, -cos_yaw * cos_pitch);
        let right = vec3(cos_yaw, 0.0, -sin_yaw);
        let up = vec3(sin_yaw * sin_pitch, cos_pitch, cos_yaw * sin_pitch);
        [view, right, up]
    }
    /// The ray setup: once a frame the corners p0 = C - right - up, p1 = C + right - up and
    /// p2 = C - right + up (the slide's camera matrix turns them with the camera's axes); then for
    /// each u and v from 0 to 1 the primary ray from O = E along D = p(u, v) - E. The corners are
    /// kept as seen from the eye (p - E), so that D is exact: a level camera's D.y is 0 at v = 0.5.
    pub fn primary_rays(&self) -> impl Fn(f64, f64) -> Ray {
        let [view, right, up] = self.axes();
        let eye = self.position;
        let center = view * SCREEN_DISTANCE; // C - E
        let p0 = center - right - up;
        let p1 = center + right - up;
        let p2 = center - right + up;
        move |u, v| Ray::new(eye, p0 + (p1 - p0) * u + (p2 - p0) * v, f64::INFINITY)
    }
}

/// The centre of pixel `i` of a row or column of the 3D view, as a fraction of its width.
fn pixel_center(i: usize) -> f64 {
    (i as f64 + 0.5) / VIEW as f64
}

// Primitives: the sphere (p - C).(p - C) = r² and the plane p.N + d = 0, each with a material.
#[derive(Clone, Copy, Debug)]
pub enum Shape {
    Sphere { center: Vec3, radius: f64 },
    Plane { normal: Vec3, offset: f64 }, // N normalized, d = offset
}

#[derive(Clone, Copy, Debug)]
pub struct Material {
    pub color: Vec3,
    pub reflectivity: f64, // 0 is matte, 1 a perfect mirror
    pub checkered: bool,   // the checkerboard of unit squares on the floor
}

impl Shape {
    /// The distance t of the ray's first hit with 0 < t < ray.t, if any.
    #[inline(always)] // for speed: inlined into each loop over the objects (a fifth faster here)
    pub fn intersect(&self, ray: &Ray) -> Option<f64> {
        let ahead = |t: f64| (t > 0.0 && t < ray.t).then_some(t);
        match *self {
            // t = -(O.N + d) / (D.N); a ray parallel to the plane (D.N = 0) misses it.
            Shape::Plane { normal, offset } => {
                let slant = ray.direction.dot(normal);
                if slant == 0.0 {
                    return None;
                }
                ahead(-(ray.origin.dot(normal) + offset) / slant)
            }
            // The slide's test: c = C - O, t = c.D, q = c - tD, p² = q.q; the hits are at
            // t -/+ sqrt(r² - p²), the far one seen from inside. A ray that only touches it misses
            // (p² = r², the slide's test lets it through): so a radius-0 sphere is never hit.
            Shape::Sphere { center, radius } => {
                let c = center - ray.origin;
                let t = c.dot(ray.direction);
                let q = c - ray.direction * t;
                let p2 = q.dot(q);
                if p2 >= radius * radius {
                    return None;
                }
                let half_chord = (radius * radius - p2).sqrt();
                ahead(t - half_chord).or(ahead(t + half_chord))
            }
        }
    }

    /// The circle (centre, radius) where a sphere meets the plane through `point` with unit
    /// normal N: around C - hN, of radius sqrt(r² - h²), where h = (C - point).N is the centre's
    /// height above the plane. None if |h| >= r, or for a plane.
    pub fn cut(&self, point: Vec3, normal: Vec3) -> Option<(Vec3, f64)> {
        let Shape::Sphere { center, radius } = *self else {
            return None;
        };
        let height = (center - point).dot(normal);
        if height.abs() >= radius {
            return None;
        }
        let circle_radius = (radius * radius - height * height).sqrt();
        Some((center - normal * height, circle_radius))
    }
}

// The scene: the objects, one point light and a flat sky.
#[derive(Debug)]
pub struct Scene {
    pub objects: Vec<(Shape, Material)>,
    pub light: Vec3,
    pub sky: Vec3,
}

impl Default for Scene {
    /// The demo: a checkered floor at y = -1 and on it four balls, one of them a mirror.
    fn default() -> Scene {
        let material = |color, reflectivity, checkered| Material {
            color,
            reflectivity,
            checkered,
        };
        let ball = |center, radius, color, reflectivity| {
            let sphere = Shape::Sphere { center, radius };
            (sphere, material(color, reflectivity, false))
        };
        let white = vec3(0.9, 0.9, 0.9);
        let floor = Shape::Plane {
            normal: vec3(0.0, 1.0, 0.0),
            offset: 1.0,
        };
        let objects = vec![
            (floor, material(white, 0.0, true)),
            ball(vec3(0.3, 0.0, -4.5), 1.0, white, 0.85),
            ball(vec3(-2.0, -0.2, -4.2), 0.8, vec3(0.9, 0.2, 0.2), 0.0),
            ball(vec3(1.9, -0.4, -3.4), 0.6, vec3(0.2, 0.8, 0.3), 0.0),
            ball(vec3(-0.9, -0.45, -2.6), 0.55, vec3(0.2, 0.4, 0.9), 0.0),
        ];
        Scene {
            objects,
            light: vec3(-3.0, 5.0, 1.0),
            sky: vec3(0.5, 0.7, 1.0),
        }
    }
}

// Shading: colour = surface × (ambient + (1 - ambient) N.L where the shadow ray reaches the light),
// mixed by the reflectivity with the colour the mirror ray R = D - 2(D.N)N brings back.
/// Where a ray hits: the point, the unit normal on the ray's side, the material.
pub type Hit = (Vec3, Vec3, Material);

impl Scene {
    /// Step 6, the nearest intersection: each object that the ray hits before ray.t shortens it.
    pub fn nearest_hit(&self, ray: &mut Ray) -> Option<Hit> {
        let mut nearest = None;
        for (shape, material) in &self.objects {
            if let Some(t) = shape.intersect(ray) {
                ray.t = t;
                nearest = Some((shape, material));
            }
        }
        let (shape, material) = nearest?;
        let point = ray.at(ray.t);
        let outward = match *shape {
            Shape::Sphere { center, radius } => (point - center) * (1.0 / radius),
            Shape::Plane { normal, .. } => normal,
        };
        // Surfaces are two-sided: N is turned to the side the ray comes from, N = -sign(D.N) N.
        let normal = outward * -outward.dot(ray.direction).signum();
        Some((point, normal, *material))
    }

    /// The shadow ray from a point to the light; none where the surface faces away (N.L <= 0).
    pub fn shadow_ray(&self, point: Vec3, normal: Vec3) -> Option<Ray> {
        let to_light = self.light - point;
        let ray = Ray::leaving(point, normal, to_light, to_light.length());
        (ray.direction.dot(normal) > 0.0).then_some(ray)
    }

    /// The colour a ray brings back, `depth` mirror bounces deep; the sky if it hits nothing.
    pub fn trace(&self, ray: &mut Ray, depth: u32) -> Vec3 {
        let hit = self.nearest_hit(ray);
        self.shade(ray, hit, depth)
    }

    /// The colour of a ray's hit; the sky if it has none.
    pub fn shade(&self, ray: &Ray, hit: Option<Hit>, depth: u32) -> Vec3 {
        let Some((point, normal, material)) = hit else {
            return self.sky;
        };
        // Lit where no object lies on the shadow ray before the light. For speed, the test stops at
        // the first object it finds there, not the nearest (15% faster here).
        let mut brightness = AMBIENT;
        if let Some(shadow) = self.shadow_ray(point, normal) {
            let blocked = |(shape, _): &(Shape, Material)| shape.intersect(&shadow).is_some();
            if !self.objects.iter().any(blocked) {
                brightness += (1.0 - AMBIENT) * shadow.direction.dot(normal);
            }
        }
        // The slide's F = ((int)(2 λ1) + (int)λ2) & 1 with λ1 = x, λ2 = z, for unit squares (no 2)
        // and with floor for (int): truncation would merge the squares either side of x = 0 and
        // of z = 0. The sum wraps instead of overflowing 10^19 units out, where any parity will do.
        if material.checkered
            && (point.x.floor() as i64).wrapping_add(point.z.floor() as i64) % 2 != 0
        {
            brightness *= ODD_SQUARE;
        }
        let color = material.color * brightness;
        if material.reflectivity <= 0.0 || depth >= MAX_DEPTH {
            return color;
        }
        let mirrored = self.trace(&mut mirror_ray(ray.direction, point, normal), depth + 1);
        color * (1.0 - material.reflectivity) + mirrored * material.reflectivity
    }
}

/// The mirror ray from a hit of a ray along D: R = D - 2(D.N)N.
pub fn mirror_ray(direction: Vec3, point: Vec3, normal: Vec3) -> Ray {
    let mirrored = direction - normal * (2.0 * direction.dot(normal));
    Ray::leaving(point, normal, mirrored, f64::INFINITY)
}

// Rendering: the 3D view's rows dealt out to all cores, then the 2D slice beside them.
/// Fills the whole 1024 x 512 frame of 0RGB pixels.
pub fn render(scene: &Scene, camera: &Camera, frame: &mut [u32]) {
    assert_eq!(frame.len(), WIDTH * VIEW, "a frame is WIDTH x VIEW pixels");
    let primary_ray = camera.primary_rays();
    let [view, _, up] = camera.axes();
    let rows = Mutex::new(frame.chunks_mut(WIDTH).enumerate());
    // Each thread takes the next row, so that all finish together: one band of rows a thread
    // measured 8.6 ms against 5.8 on 2 cores, as the sky's band is done first.
    let next_row = || rows.lock().unwrap().next();
    let threads = std::thread::available_parallelism().map_or(1, usize::from);
    std::thread::scope(|scope| {
        for _ in 0..threads {
            scope.spawn(|| {
                while let Some((y, row)) = next_row() {
                    let v = 1.0 - pixel_center(y); // rows count down from the top, v up from p0
                    // For speed (the same image; a fifth fewer instructions, 10% faster here): the
                    // row's rays lie in one plane through the eye, so their nearest hits are sought
                    // only among the planes and the spheres that it cuts (the shading still uses the
                    // whole scene: shadow and mirror rays leave that plane). Its normal is at right
                    // angles to right and to dV + (2v - 1) up.
                    let row_plane = (up * SCREEN_DISTANCE - view * (2.0 * v - 1.0)).normalize();
                    let reachable = |(shape, _): &&(Shape, Material)| match shape {
                        Shape::Sphere { .. } => shape.cut(camera.position, row_plane).is_some(),
                        Shape::Plane { .. } => true,
                    };
                    let objects = scene.objects.iter().filter(reachable).copied().collect();
                    let row_scene = Scene { objects, ..*scene };
                    // For speed: all the row's rays first, so that their square roots overlap (a
                    // fifth faster here).
                    let mut rays: Vec<Ray> =
                        (0..VIEW).map(|x| primary_ray(pixel_center(x), v)).collect();
                    for (pixel, ray) in row[..VIEW].iter_mut().zip(&mut rays) {
                        let hit = row_scene.nearest_hit(ray);
                        *pixel = to_rgb(scene.shade(ray, hit, 0));
                    }
                }
            });
        }
    });
    draw_slice(scene, camera, frame);
}

/// A colour as a 0RGB pixel, each channel clamped to at most 1 (shading never makes it negative).
pub fn to_rgb(color: Vec3) -> u32 {
    let byte = |channel: f64| (channel.min(1.0) * 255.0) as u32;
    byte(color.x) << 16 | byte(color.y) << 8 | byte(color.z)
}

// The 2D slice: the plane through the eye that holds the screen's middle line (v = 0.5), seen
// from straight above with x to the right and -z up (a tilted plane looks squashed from above);
// every 10th ray of that line with its hit, its shadow ray and its mirror ray.
pub const MAP_CORNER: Vec3 = vec3(-6.4, 0.0, -9.4); // top left x and z: 12.8 units around the demo
pub const MAP_SCALE: f64 = 40.0; // map pixels per world unit
const OUTLINE_SEGMENTS: u32 = 64; // straight pieces in the outline of a cut sphere
const SAMPLED_EVERY: usize = 10; // the assignment's "every 10th ray"
const DOT_RADIUS: i32 = 2; // a dot is 5 x 5 map pixels: 2 either side of its point
pub const CAMERA_COLOR: u32 = 0xffffff; // white: the eye and the screen's middle line
pub const RAY_COLOR: u32 = 0xffff00; // yellow: a sampled ray up to its hit, and the hit
pub const MISS_COLOR: u32 = 0x4070b0; // steel blue: a ray that hits nothing, to the map's edge
pub const LIGHT_COLOR: u32 = 0xff6000; // orange: the light, and a shadow ray that reaches it
pub const BLOCKED_COLOR: u32 = 0xa040ff; // violet: a shadow ray, up to what blocks it
pub const MIRROR_COLOR: u32 = 0x00e0ff; // cyan: a mirror ray, up to what it hits

/// Colours the map pixels up to `radius` pixels either side of a world point, where on the map.
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

/// Draws p(t) for 0 <= t <= ray.t seen from above: a dot every map pixel along it, the last less
/// than a pixel before its end, wherever its ends are.
fn draw_ray(frame: &mut [u32], ray: &Ray, color: u32) {
    let speed = ray.direction.x.hypot(ray.direction.z) * MAP_SCALE; // map pixels per unit of t
    if speed == 0.0 {
        return; // straight up or down: the dot at its start shows it
    }
    let map_middle = vec3(0.5, 0.0, 0.5) * VIEW as f64; // in map pixels
    let origin = (ray.origin - MAP_CORNER) * MAP_SCALE - map_middle; // p(0), from the middle
    let distance = origin.x.hypot(origin.z);
    // The dot of step s is at least |distance - s| pixels from the map's middle, and every map
    // pixel is within VIEW of it (VIEW / √2 at the corners): so only steps from distance - VIEW to
    // distance + VIEW can be on the map.
    let first = (distance - VIEW as f64).max(0.0);
    let last = (ray.t * speed).min(distance + VIEW as f64);
    for step in first as usize..=last as usize {
        plot(frame, ray.at(step as f64 / speed), 0, color);
    }
}

/// Draws the segment from `from` to `to`.
fn draw_line(frame: &mut [u32], from: Vec3, to: Vec3, color: u32) {
    let length = (to - from).length();
    draw_ray(frame, &Ray::new(from, to - from, length), color);
}

/// Follows a ray to its nearest hit and draws it that far: in the first colour if it hits
/// something before ray.t, in the second if not.
fn follow(frame: &mut [u32], scene: &Scene, mut ray: Ray, colors: [u32; 2]) -> Option<Hit> {
    let hit = scene.nearest_hit(&mut ray);
    let [hit_color, miss_color] = colors;
    let color = if hit.is_some() { hit_color } else { miss_color };
    draw_ray(frame, &ray, color);
    hit
}

/// The right half: on black, the outlines where the slice plane cuts the spheres, the sampled rays,
/// the screen, the light and the camera.
fn draw_slice(scene: &Scene, camera: &Camera, frame: &mut [u32]) {
    for row in frame.chunks_mut(WIDTH) {
        row[VIEW..].fill(0);
    }
    let [view, right, up] = camera.axes(); // the slice plane holds V and right; up is its normal
    let eye = camera.position;
    for (shape, material) in &scene.objects {
        let Some((center, radius)) = shape.cut(eye, up) else {
            continue;
        };
        let around = |i: u32| {
            let angle = TAU * i as f64 / OUTLINE_SEGMENTS as f64;
            center + (right * angle.cos() + view * angle.sin()) * radius
        };
        for i in 0..OUTLINE_SEGMENTS {
            draw_line(frame, around(i), around(i + 1), to_rgb(material.color));
        }
    }
    let primary_ray = camera.primary_rays();
    for x in (0..VIEW).step_by(SAMPLED_EVERY) {
        let ray = primary_ray(pixel_center(x), 0.5);
        let Some((point, normal, material)) = follow(frame, scene, ray, [RAY_COLOR, MISS_COLOR])
        else {
            continue;
        };
        if let Some(shadow) = scene.shadow_ray(point, normal) {
            follow(frame, scene, shadow, [BLOCKED_COLOR, LIGHT_COLOR]);
        }
        if material.reflectivity > 0.0 {
            let mirror = mirror_ray(ray.direction, point, normal);
            follow(frame, scene, mirror, [MIRROR_COLOR, MISS_COLOR]);
        }
        plot(frame, point, DOT_RADIUS, RAY_COLOR);
    }
    let screen = eye + view * SCREEN_DISTANCE; // C: the screen's middle line, over the rays
    draw_line(frame, screen - right, screen + right, CAMERA_COLOR);
    plot(frame, scene.light, DOT_RADIUS, LIGHT_COLOR);
    plot(frame, eye, DOT_RADIUS, CAMERA_COLOR);
}

// The program: a window whose keys move and turn the camera; it renders when the view changes.
const USAGE: &str =
    "usage: raytracer (no arguments: it opens a window, whose title lists the keys)";
const TITLE: &str = "raytracer - W A S D R F move, arrow keys turn, Escape quits";
const MOVE_SPEED: f64 = 2.0; // units a second
const TURN_SPEED: f64 = 1.5; // radians a second
const STEPS_PER_SECOND: usize = 60; // the keys are read 60 times a second
const REDRAW_STEPS: u64 = 10; // idle, the window is redrawn every 10th step: 6 times a second

fn main() {
    let arguments: Vec<String> = std::env::args().skip(1).collect();
    if arguments == ["--help"] {
        writeln!(std::io::stdout(), "{USAGE}").ok(); // a closed stdout is no error here
        return;
    }
    if !arguments.is_empty() {
        eprintln!("{USAGE}");
        std::process::exit(2);
    }
    let options = WindowOptions::default();
    let mut window = Window::new(TITLE, WIDTH, VIEW, options).unwrap_or_else(|error| {
        eprintln!("raytracer: cannot open the window: {error}");
        std::process::exit(1)
    });
    window.set_target_fps(STEPS_PER_SECOND); // it sleeps for the rest of each step
    let scene = Scene::default();
    let mut camera = Camera::default();
    let mut shown = None; // the camera of the frame on screen
    let mut frame = vec![0; WIDTH * VIEW];
    let mut last_step = Instant::now();
    let mut steps = 0u64;
    let mut stale = Vec::new(); // keys down while the window lacked the focus, not yet let go
    while window.is_open() && !window.is_key_down(Key::Escape) {
        steps += 1;
        let dt = last_step.elapsed().as_secs_f64();
        last_step = Instant::now();
        // X11 does not tell a window of a key let go while it lacks the focus, so the key stays
        // down: while it lacks the focus every key down is stale, and stays so until let go.
        if !window.is_active() {
            stale = window.get_keys();
        }
        stale.retain(|&key| window.is_key_down(key));
        let down = |key| window.is_key_down(key) && !stale.contains(&key);
        let held = |key| if down(key) { dt } else { 0.0 };
        let [view, right, _] = camera.axes();
        let forward = view * (held(Key::W) - held(Key::S));
        let sideways = right * (held(Key::D) - held(Key::A));
        let rise = vec3(0.0, held(Key::R) - held(Key::F), 0.0);
        camera.position = camera.position + (forward + sideways + rise) * MOVE_SPEED;
        camera.yaw += TURN_SPEED * (held(Key::Left) - held(Key::Right));
        let pitch = camera.pitch + TURN_SPEED * (held(Key::Up) - held(Key::Down));
        camera.pitch = pitch.clamp(-FRAC_PI_2, FRAC_PI_2); // straight up at most, never over
        let moved = shown != Some(camera);
        if moved {
            let start = Instant::now();
            render(&scene, &camera, &mut frame);
            let milliseconds = start.elapsed().as_secs_f64() * 1e3;
            window.set_title(&format!("{TITLE} - {milliseconds:.1} ms a frame"));
            shown = Some(camera);
        }
        // Idle, only the keys are read; the frame is shown again now and then, as X forgets what
        // a covered window showed.
        if moved || steps.is_multiple_of(REDRAW_STEPS) {
            window.update_with_buffer(&frame, WIDTH, VIEW).ok(); // it fails only for a wrong size
        } else {
            window.update();
        }
    }
}
