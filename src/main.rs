//! A Whitted-style ray tracer in one file: spheres and a checkered floor, one point light, hard
//! shadows and mirror reflections, and beside the 3D view a top-down 2D slice of the scene.
use minifb::{Key, Window, WindowOptions};
use std::f64::consts::{FRAC_PI_2, TAU};
use std::{ops, sync::Mutex, time::Instant};

pub const VIEW: usize = 512; // each half of the window is VIEW x VIEW pixels
pub const WIDTH: usize = 2 * VIEW; // a row of the frame: the 3D view, then the 2D slice
pub const EPSILON: f64 = 1e-6; // a hit closer than this is the surface the ray starts on
pub const MAX_DEPTH: u32 = 5; // mirror bounces followed at most
pub const AMBIENT: f64 = 0.1; // the light a surface gets even in shadow

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
    pub fn cross(self, other: Vec3) -> Vec3 {
        let (a, b) = (self, other);
        vec3(
            a.y * b.z - a.z * b.y,
            a.z * b.x - a.x * b.z,
            a.x * b.y - a.y * b.x,
        )
    }
    pub fn length(self) -> f64 {
        self.dot(self).sqrt()
    }
    pub fn normalize(self) -> Vec3 {
        self * (1.0 / self.length())
    }
}

macro_rules! componentwise {
    ($trait:ident, $method:ident, $op:tt) => {
        impl ops::$trait for Vec3 {
            type Output = Vec3;
            fn $method(self, other: Vec3) -> Vec3 {
                vec3(self.x $op other.x, self.y $op other.y, self.z $op other.z)
            }
        }
    };
}
componentwise!(Add, add, +);
componentwise!(Sub, sub, -);

impl ops::Mul<f64> for Vec3 {
    type Output = Vec3;
    fn mul(self, scale: f64) -> Vec3 {
        vec3(self.x * scale, self.y * scale, self.z * scale)
    }
}

// The ray: p(t) = O + tD with t > 0 and D normalized.
#[derive(Clone, Copy, Debug)]
pub struct Ray {
    pub origin: Vec3,
    pub direction: Vec3,
}

impl Ray {
    pub fn new(origin: Vec3, towards: Vec3) -> Ray {
        let direction = towards.normalize();
        Ray { origin, direction }
    }
    pub fn at(&self, t: f64) -> Vec3 {
        self.origin + self.direction * t
    }
}

// The camera: eye E, view direction V, screen centre C = E + dV with d = 1 (a 90 degree field of
// view), corners p0 (top left), p1 (top right), p2 (bottom left), and for pixel (u, v) the point
// p(u, v) = p0 + u(p1 - p0) + v(p2 - p0) and the primary ray D = p(u, v) - E.
#[derive(Clone, Copy, Debug, Default)]
pub struct Camera {
    pub position: Vec3,
    pub yaw: f64,   // radians about +y; positive turns the view left
    pub pitch: f64, // radians; positive looks up, taken within +-90 degrees so the view never flips
}

/// The unit vector for a yaw and a pitch; (0, 0) looks down -z.
pub fn direction(yaw: f64, pitch: f64) -> Vec3 {
    let (horizontal, y) = (pitch.cos(), pitch.sin());
    vec3(-yaw.sin() * horizontal, y, -yaw.cos() * horizontal)
}

impl Camera {
    /// The screen's corners [p0, p1, p2]: 1 to the right and 1 up from the centre.
    pub fn screen(&self) -> [Vec3; 3] {
        let center = self.position + direction(self.yaw, self.pitch);
        let right = direction(self.yaw - FRAC_PI_2, 0.0);
        let up = direction(self.yaw, self.pitch + FRAC_PI_2);
        let (top, bottom) = (center + up, center - up);
        [top - right, top + right, bottom - right]
    }
    /// The primary ray through the centre of pixel (x, y) of the 3D view, row 0 at the top.
    pub fn primary_ray(&self, [p0, p1, p2]: [Vec3; 3], x: usize, y: usize) -> Ray {
        let [u, v] = [x, y].map(|pixel| (pixel as f64 + 0.5) / VIEW as f64);
        let on_screen = p0 + (p1 - p0) * u + (p2 - p0) * v;
        Ray::new(self.position, on_screen - self.position)
    }
}

// Primitives: the sphere |p - C|² = r² and the plane p.N + d = 0, each with a material.
#[derive(Clone, Copy, Debug)]
pub enum Shape {
    Sphere { center: Vec3, radius: f64 },
    Plane { normal: Vec3, offset: f64 }, // N normalized, d = offset
}

#[derive(Clone, Copy, Debug)]
pub struct Material {
    pub color: Vec3,
    pub reflectivity: f64, // 0 is matte, 1 a perfect mirror
    pub checkered: bool,   // the checkerboard: darker where floor(x) + floor(z) is odd
}

impl Shape {
    /// The distance t to the nearest hit in front of the ray, if there is one.
    #[inline] // called for every shape and every ray: the hottest code
    pub fn intersect(&self, ray: &Ray) -> Option<f64> {
        let ahead = |t: f64| (t > EPSILON && t < f64::INFINITY).then_some(t);
        match *self {
            // t = -(O.N + d) / (D.N): infinite or NaN for a ray parallel to the plane, so no hit.
            Shape::Plane { normal, offset } => {
                ahead(-(ray.origin.dot(normal) + offset) / ray.direction.dot(normal))
            }
            // Project C on the ray, t_c = (C - O).D, where it passes C at p² = |C - O|² - t_c²;
            // the hits are half a chord, sqrt(r² - p²), either side: the far one from inside.
            Shape::Sphere { center, radius } => {
                let to_center = center - ray.origin;
                let t_center = to_center.dot(ray.direction);
                let p2 = to_center.dot(to_center) - t_center * t_center;
                if p2 >= radius * radius {
                    return None;
                }
                let half_chord = (radius * radius - p2).sqrt();
                ahead(t_center - half_chord).or(ahead(t_center + half_chord))
            }
        }
    }
}

// The scene: the objects, one point light and a flat sky.
pub type Object = (Shape, Material);

#[derive(Clone, Debug)]
pub struct Scene {
    pub objects: Vec<Object>,
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
        let (normal, offset, white) = (vec3(0.0, 1.0, 0.0), 1.0, vec3(0.9, 0.9, 0.9));
        let objects = vec![
            (Shape::Plane { normal, offset }, material(white, 0.0, true)),
            ball(vec3(0.3, 0.0, -4.5), 1.0, white, 0.85),
            ball(vec3(-2.0, -0.2, -4.2), 0.8, vec3(0.9, 0.2, 0.2), 0.0),
            ball(vec3(1.9, -0.4, -3.4), 0.6, vec3(0.2, 0.8, 0.3), 0.0),
            ball(vec3(-0.9, -0.45, -2.6), 0.55, vec3(0.2, 0.4, 0.9), 0.0),
        ];
        let (light, sky) = (vec3(-3.0, 5.0, 1.0), vec3(0.5, 0.7, 1.0));
        Scene {
            objects,
            light,
            sky,
        }
    }
}

// Shading: colour = surface × (ambient + N.L where the shadow ray reaches the light), mixed by
// the reflectivity with the colour the mirror ray R = D - 2(D.N)N brings back.
/// The nearest hit among `objects`: its point, the unit normal facing the ray, its material.
pub fn nearest_hit<'a>(objects: &'a [Object], ray: &Ray) -> Option<(Vec3, Vec3, &'a Material)> {
    let (t, shape, material) = (objects.iter())
        .filter_map(|(shape, material)| Some((shape.intersect(ray)?, shape, material)))
        .min_by(|a, b| a.0.total_cmp(&b.0))?;
    let point = ray.at(t);
    let normal = match *shape {
        Shape::Sphere { center, radius } => (point - center) * (1.0 / radius),
        Shape::Plane { normal, .. } => normal,
    };
    let facing = normal * -normal.dot(ray.direction).signum(); // the side the ray comes from
    Some((point, facing, material))
}

impl Scene {
    /// The colour a ray brings back, its first hit looked for among `objects` (all of the scene's,
    /// or those its row can reach); `rays` counts every ray traced, shadow rays too.
    pub fn trace(&self, ray: &Ray, objects: &[Object], depth: u32, rays: &mut u64) -> Vec3 {
        *rays += 1;
        let Some((point, normal, material)) = nearest_hit(objects, ray) else {
            return self.sky;
        };
        let to_light = Ray::new(point, self.light - point);
        let facing_light = normal.dot(to_light.direction);
        let mut brightness = AMBIENT;
        if facing_light > 0.0 && !self.in_shadow(&to_light, rays) {
            brightness += (1.0 - AMBIENT) * facing_light;
        }
        let odd = (floor(point.x) + floor(point.z)) & 1 == 1;
        let checker = if material.checkered && odd { 0.25 } else { 1.0 };
        let color = material.color * (checker * brightness);
        if material.reflectivity <= 0.0 || depth >= MAX_DEPTH {
            return color;
        }
        let mirror = Ray::new(point, reflect(ray.direction, normal));
        let mirrored = self.trace(&mirror, &self.objects, depth + 1, rays);
        color * (1.0 - material.reflectivity) + mirrored * material.reflectivity
    }

    /// Does an object lie between the shadow ray's origin and the light?
    fn in_shadow(&self, ray: &Ray, rays: &mut u64) -> bool {
        *rays += 1;
        let distance = (self.light - ray.origin).length();
        (self.objects.iter()).any(|(shape, _)| shape.intersect(ray).is_some_and(|t| t < distance))
    }
}

/// The mirror direction R = D - 2(D.N)N.
pub fn reflect(direction: Vec3, normal: Vec3) -> Vec3 {
    direction - normal * (2.0 * direction.dot(normal))
}

/// floor(w) as an integer: the cast rounds towards zero, one too high for negative fractions.
/// (f64::floor is a library call on the x86-64 baseline, about 5% of a frame's instructions.)
pub fn floor(w: f64) -> i64 {
    let towards_zero = w as i64;
    towards_zero - (w < towards_zero as f64) as i64
}

// Rendering a 1024x512 frame: the 3D view on the left on all cores, the 2D slice on the right.
/// Renders the whole frame on all cores and returns the number of rays traced.
pub fn render(scene: &Scene, camera: &Camera, frame: &mut [u32]) -> u64 {
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    render_on(scene, camera, frame, threads)
}

/// The frame on `threads` threads: each takes the next row of the 3D view until none are left,
/// this one after drawing the 2D slice.
pub fn render_on(scene: &Scene, camera: &Camera, frame: &mut [u32], threads: usize) -> u64 {
    assert_eq!(frame.len(), WIDTH * VIEW, "a frame is 1024 x 512 pixels");
    let screen = camera.screen();
    let halves = frame.chunks_mut(WIDTH).map(|row| row.split_at_mut(VIEW));
    let (view, mut map): (Vec<_>, Vec<_>) = halves.unzip();
    let rows = Mutex::new(view.into_iter().enumerate());
    let trace_rows = || {
        let mut rays = 0;
        for (y, row) in std::iter::from_fn(|| rows.lock().unwrap().next()) {
            let reachable = row_objects(scene, camera, screen, y);
            for (x, pixel) in row.iter_mut().enumerate() {
                let ray = camera.primary_ray(screen, x, y);
                *pixel = to_rgb(scene.trace(&ray, &reachable, 0, &mut rays));
            }
        }
        rays
    };
    std::thread::scope(|scope| {
        let workers: Vec<_> = (1..threads).map(|_| scope.spawn(trace_rows)).collect();
        draw_slice(scene, camera, &mut map);
        let counts = workers.into_iter().map(|worker| worker.join().unwrap());
        trace_rows() + counts.sum::<u64>()
    })
}

/// The objects a row's primary rays can hit. They fan out in one plane through the eye, from the
/// first ray to the last: a sphere further than r from that plane is missed by all of them, and a
/// plane is hit only if the first or the last heads towards it (D.N and O.N + d of unlike signs).
pub fn row_objects(scene: &Scene, camera: &Camera, screen: [Vec3; 3], y: usize) -> Vec<Object> {
    let first = camera.primary_ray(screen, 0, y).direction;
    let last = camera.primary_ray(screen, VIEW - 1, y).direction;
    let fan_normal = first.cross(last).normalize();
    let reachable = |(shape, _): &&Object| match *shape {
        Shape::Sphere { center, radius } => {
            let distance = (center - camera.position).dot(fan_normal).abs();
            distance < radius + EPSILON // a little slack for rounding
        }
        Shape::Plane { normal, offset } => {
            let side = camera.position.dot(normal) + offset;
            first.dot(normal) * side < 0.0 || last.dot(normal) * side < 0.0
        }
    };
    scene.objects.iter().filter(reachable).copied().collect()
}

/// A colour as a 0RGB pixel, each channel clamped to [0, 1].
pub fn to_rgb(color: Vec3) -> u32 {
    let byte = |channel: f64| (channel.min(1.0) * 255.0) as u32; // `as` takes negatives to 0
    byte(color.x) << 16 | byte(color.y) << 8 | byte(color.z)
}

// The 2D slice: the plane at the eye's height seen from above, x to the right and -z up.
pub const MAP_CORNER: Vec3 = vec3(-6.4, 0.0, -9.4); // the world x and z at the map's top left
pub const MAP_SCALE: f64 = 40.0; // map pixels per world unit

/// Colours the map pixel under a world point; `map` holds the right half of each row.
fn plot(map: &mut [&mut [u32]], point: Vec3, color: u32) {
    let [x, y] = [point.x - MAP_CORNER.x, point.z - MAP_CORNER.z].map(|w| w * MAP_SCALE);
    if (0.0..VIEW as f64).contains(&x) && (0.0..VIEW as f64).contains(&y) {
        map[y as usize][x as usize] = color;
    }
}

/// A dot of 5 x 5 map pixels.
fn draw_dot(map: &mut [&mut [u32]], point: Vec3, color: u32) {
    for i in 0..25 {
        let offset = vec3((i % 5) as f64 - 2.0, 0.0, (i / 5) as f64 - 2.0);
        plot(map, point + offset * (1.0 / MAP_SCALE), color);
    }
}

/// A segment as a dot per map pixel, clipped to the map's edges first: far ends cost nothing.
fn draw_line(map: &mut [&mut [u32]], from: Vec3, to: Vec3, color: u32) {
    let (mut enter, mut leave) = (0.0f64, 1.0f64);
    for (start, end, edge) in [(from.x, to.x, MAP_CORNER.x), (from.z, to.z, MAP_CORNER.z)] {
        let [t0, t1] = [edge, edge + VIEW as f64 / MAP_SCALE].map(|e| (e - start) / (end - start));
        (enter, leave) = (enter.max(t0.min(t1)), leave.min(t0.max(t1)));
    }
    let dots = ((to - from).length() * MAP_SCALE * (leave - enter)).ceil() as usize;
    for t in (0..dots).map(|i| enter + (leave - enter) * (i as f64 + 0.5) / dots as f64) {
        plot(map, from + (to - from) * t, color);
    }
}

/// The right half: spheres, screen, every 10th ray of the middle row with its hit, light, camera.
pub fn draw_slice(scene: &Scene, camera: &Camera, map: &mut [&mut [u32]]) {
    const FAR: f64 = 1e6; // where a ray that hits nothing is drawn to: past the map's edge
    for row in map.iter_mut() {
        row.fill(0x202020);
    }
    let eye = camera.position;
    for (shape, material) in &scene.objects {
        if let Shape::Sphere { center, radius } = *shape {
            // It cuts the plane y = eye.y in a circle of radius² = r² - (C.y - eye.y)², drawn as
            // 64 segments (none for a NaN radius: the sphere misses the plane).
            let cut = (radius * radius - (center.y - eye.y).powi(2)).sqrt();
            let around = |i: u32| center + direction(TAU * i as f64 / 64.0, 0.0) * cut;
            for i in 0..64 {
                draw_line(map, around(i), around(i + 1), to_rgb(material.color));
            }
        }
    }
    let screen @ [p0, p1, p2] = camera.screen();
    for x in (0..VIEW).step_by(10) {
        let ray = camera.primary_ray(screen, x, VIEW / 2);
        let Some((point, normal, material)) = nearest_hit(&scene.objects, &ray) else {
            draw_line(map, eye, ray.at(FAR), 0x808080);
            continue;
        };
        draw_line(map, eye, point, 0xc0c040);
        draw_line(map, point, scene.light, 0x606060);
        if material.reflectivity > 0.0 {
            let mirror = Ray::new(point, reflect(ray.direction, normal));
            let bounce = nearest_hit(&scene.objects, &mirror).map(|hit| hit.0);
            let bounce = bounce.unwrap_or(mirror.at(FAR));
            draw_line(map, point, bounce, 0x40c0ff);
        }
        draw_dot(map, point, 0xff4040);
    }
    let to_middle_row = (p2 - p0) * 0.5; // the screen's middle row, drawn over the rays
    draw_line(map, p0 + to_middle_row, p1 + to_middle_row, 0xffffff);
    draw_dot(map, scene.light, 0xffff00);
    draw_dot(map, eye, 0xffffff);
}

// The program: the window and its controls, or headless --bench and --screenshot.
const USAGE: &str = "usage: raytracer [--bench [FRAMES] | --screenshot FILE.ppm]";

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.iter().map(String::as_str).collect::<Vec<_>>()[..] {
        [] => run_window(),
        ["--bench"] => bench(100),
        ["--bench", frames] => match frames.parse() {
            Ok(frames) if frames > 0 => bench(frames),
            _ => exit_with(2, USAGE),
        },
        ["--screenshot", path] => screenshot(path),
        _ => exit_with(2, USAGE),
    }
}

/// Ends the program with one line on stderr: status 1 for a failure, 2 for a bad command line.
fn exit_with(status: i32, message: &str) -> ! {
    eprintln!("raytracer: {message}");
    std::process::exit(status);
}

fn run_window() {
    let options = WindowOptions::default();
    let mut window = Window::new("raytracer", WIDTH, VIEW, options).unwrap_or_else(|error| {
        exit_with(1, &format!("cannot open a window: no display? ({error})"))
    });
    println!("W/S forward/back, A/D left/right, R/F up/down, arrow keys turn, Escape quits");
    let (scene, mut camera) = (Scene::default(), Camera::default());
    let mut frame = vec![0; WIDTH * VIEW];
    let mut last_frame = Instant::now();
    while window.is_open() && !window.is_key_down(Key::Escape) {
        let dt = last_frame.elapsed().as_secs_f64();
        last_frame = Instant::now();
        // Each key held moves or turns by speed × the seconds the last frame took.
        let held = |key| if window.is_key_down(key) { dt } else { 0.0 };
        let forward = direction(camera.yaw, camera.pitch) * (held(Key::W) - held(Key::S));
        let right = direction(camera.yaw - FRAC_PI_2, 0.0) * (held(Key::D) - held(Key::A));
        let up = vec3(0.0, held(Key::R) - held(Key::F), 0.0);
        camera.position = camera.position + (forward + right + up) * 2.0;
        camera.yaw += 1.5 * (held(Key::Left) - held(Key::Right));
        let pitch = camera.pitch + 1.5 * (held(Key::Up) - held(Key::Down));
        camera.pitch = pitch.clamp(-FRAC_PI_2, FRAC_PI_2);
        render(&scene, &camera, &mut frame);
        window.set_title(&format!("raytracer - {:.0} fps", 1.0 / dt));
        let shown = window.update_with_buffer(&frame, WIDTH, VIEW);
        shown.unwrap_or_else(|error| exit_with(1, &error.to_string()));
    }
}

fn bench(frames: usize) {
    let (scene, camera) = (Scene::default(), Camera::default());
    let mut frame = vec![0; WIDTH * VIEW];
    let (mut rays, mut milliseconds) = (0, Vec::new());
    for _ in 0..frames {
        let start = Instant::now();
        rays = render(&scene, &camera, &mut frame);
        milliseconds.push(start.elapsed().as_secs_f64() * 1e3);
    }
    milliseconds.sort_by(f64::total_cmp);
    let (median, min) = (milliseconds[frames / 2], milliseconds[0]);
    let (fps, mrays) = (1e3 / median, rays as f64 / median / 1e3);
    let (primary, secondary) = (VIEW * VIEW, rays as usize - VIEW * VIEW);
    let timing = format!("{frames} frames: median {median:.2} ms, min {min:.2} ms, {fps:.0} fps");
    let counts = format!("{primary} primary + {secondary} shadow and mirror rays a frame");
    println!("{timing}\n{mrays:.1} Mrays/s: {counts}"); // one write: `| head -1` gets no broken pipe
}

fn screenshot(path: &str) {
    let mut frame = vec![0; WIDTH * VIEW];
    render(&Scene::default(), &Camera::default(), &mut frame);
    let mut ppm = format!("P6\n{WIDTH} {VIEW}\n255\n").into_bytes();
    let red_green_blue = |pixel: &u32| pixel.to_be_bytes().into_iter().skip(1);
    ppm.extend(frame.iter().flat_map(red_green_blue));
    let written = std::fs::write(path, ppm);
    written.unwrap_or_else(|error| exit_with(1, &format!("cannot write {path}: {error}")));
}
