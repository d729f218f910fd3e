//! A Whitted-style ray tracer in one file: spheres and a checkered floor, one point light, hard
//! shadows and mirror reflections, and beside the 3D view a top-down 2D slice of the scene.
use minifb::{Key, Window, WindowOptions};
use std::f64::consts::{FRAC_PI_2, TAU};
use std::{ops, sync::Mutex, time::Instant};

pub const VIEW: usize = 512; // each half of the window is VIEW x VIEW pixels
pub const WIDTH: usize = 2 * VIEW; // a row of the frame: the 3D view, then the 2D slice
const EPSILON: f64 = 1e-6; // a hit closer than this is the surface the ray starts on
pub const MAX_DEPTH: u32 = 5; // mirror bounces followed at most
pub const AMBIENT: f64 = 0.1; // the light a surface gets even in shadow

// Vector math: points, directions and colours (x, y, z = red, green, blue) are all a Vec3.
#[derive(Clone, Copy, Debug, Default)]
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
    fn cross(self, other: Vec3) -> Vec3 {
        vec3(
            self.y * other.z - self.z * other.y,
            self.z * other.x - self.x * other.z,
            self.x * other.y - self.y * other.x,
        )
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
        self + other * -1.0
    }
}

impl ops::Mul<f64> for Vec3 {
    type Output = Vec3;
    fn mul(self, scale: f64) -> Vec3 {
        vec3(self.x * scale, self.y * scale, self.z * scale)
    }
}

// The ray: p(t) = O + tD with t > 0 and D normalized.
pub struct Ray {
    pub origin: Vec3,
    pub direction: Vec3,
}

impl Ray {
    pub fn new(origin: Vec3, towards: Vec3) -> Ray {
        let direction = towards.normalize();
        Ray { origin, direction }
    }
}

// The camera: eye E, view V, screen centre C = E + V (d = 1: 90 degrees), corners p0 top left, p1
// top right, p2 bottom left; p(u, v) = p0 + u(p1 - p0) + v(p2 - p0) and the ray D = p(u, v) - E.
#[derive(Debug, Default)]
pub struct Camera {
    pub position: Vec3,
    pub yaw: f64,   // radians about +y; positive turns the view left
    pub pitch: f64, // radians; positive looks up
}

/// The unit vector for a yaw and a pitch; (0, 0) looks down -z.
fn direction(yaw: f64, pitch: f64) -> Vec3 {
    let level = pitch.cos(); // the length of its horizontal part
    vec3(-yaw.sin() * level, pitch.sin(), -yaw.cos() * level)
}

impl Camera {
    /// The screen seen from the eye: p0 - E, p1 - p0 and p2 - p0.
    pub fn screen(&self) -> [Vec3; 3] {
        let right = direction(self.yaw - FRAC_PI_2, 0.0) * 2.0;
        let down = direction(self.yaw, self.pitch - FRAC_PI_2) * 2.0;
        let top_left = direction(self.yaw, self.pitch) - (right + down) * 0.5;
        [top_left, right, down]
    }
    pub fn primary_ray(&self, [top_left, right, down]: [Vec3; 3], u: f64, v: f64) -> Ray {
        Ray::new(self.position, top_left + right * u + down * v)
    }
}

/// The centre of pixel `i` of a row or column of the 3D view, as a fraction of its width.
fn pixel_center(i: usize) -> f64 {
    (i as f64 + 0.5) / VIEW as f64
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
    /// The distance t of the nearest hit in front of the ray and nearer than `max`, if any.
    pub fn intersect(&self, ray: &Ray, max: f64) -> Option<f64> {
        let ahead = |t: f64| (t > EPSILON && t < max).then_some(t);
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
type Object = (Shape, Material);

#[derive(Debug)]
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
        Scene {
            objects,
            light: vec3(-3.0, 5.0, 1.0),
            sky: vec3(0.5, 0.7, 1.0),
        }
    }
}

// Shading: colour = surface × (ambient + N.L where the shadow ray reaches the light), mixed by
// the reflectivity with the colour the mirror ray R = D - 2(D.N)N brings back.
/// The nearest hit: its point, the unit normal facing the ray, its material.
fn nearest_hit(objects: &[Object], ray: &Ray) -> Option<(Vec3, Vec3, Material)> {
    let (mut t, mut nearest) = (f64::INFINITY, None);
    for object in objects {
        if let Some(hit) = object.0.intersect(ray, t) {
            (t, nearest) = (hit, Some(object));
        }
    }
    let (shape, material) = nearest?;
    let point = ray.origin + ray.direction * t;
    let normal = match *shape {
        Shape::Sphere { center, radius } => (point - center) * (1.0 / radius),
        Shape::Plane { normal, .. } => normal,
    };
    let facing = normal * -normal.dot(ray.direction).signum(); // the side the ray comes from
    Some((point, facing, *material))
}

impl Scene {
    /// The colour a ray brings back, its first hit among `objects`, after `depth` mirror bounces.
    pub fn trace(&self, ray: &Ray, objects: &[Object], depth: u32) -> Vec3 {
        let Some((point, normal, material)) = nearest_hit(objects, ray) else {
            return self.sky;
        };
        // The shadow ray: lit when no object lies nearer than the light.
        let to_light = self.light - point;
        let distance = to_light.length();
        let shadow_ray = Ray::new(point, to_light);
        let facing_light = normal.dot(shadow_ray.direction);
        let mut brightness = AMBIENT;
        let blocked = |(shape, _): &Object| shape.intersect(&shadow_ray, distance).is_some();
        if facing_light > 0.0 && !self.objects.iter().any(blocked) {
            brightness += (1.0 - AMBIENT) * facing_light;
        }
        let odd = material.checkered && (point.x.floor() + point.z.floor()) as i64 & 1 == 1;
        let color = material.color * (brightness * if odd { 0.25 } else { 1.0 });
        if material.reflectivity <= 0.0 || depth >= MAX_DEPTH {
            return color;
        }
        let mirrored = self.trace(&reflect(ray, point, normal), &self.objects, depth + 1);
        color * (1.0 - material.reflectivity) + mirrored * material.reflectivity
    }
}

/// The mirror ray from a hit: R = D - 2(D.N)N.
fn reflect(ray: &Ray, point: Vec3, normal: Vec3) -> Ray {
    let direction = ray.direction - normal * (2.0 * ray.direction.dot(normal));
    Ray::new(point, direction)
}

// Rendering: the 3D view's rows dealt out to all cores, then the 2D slice beside them.
/// Fills the whole 1024 x 512 frame of 0RGB pixels.
pub fn render(scene: &Scene, camera: &Camera, frame: &mut [u32]) {
    let screen = camera.screen();
    let rows = Mutex::new(frame.chunks_mut(WIDTH).enumerate());
    let threads = std::thread::available_parallelism().map_or(1, usize::from);
    std::thread::scope(|scope| {
        for _ in 0..threads {
            scope.spawn(|| {
                for (y, row) in std::iter::from_fn(|| rows.lock().unwrap().next()) {
                    let ray = |u| camera.primary_ray(screen, u, pixel_center(y));
                    let reachable = row_objects(scene, ray(0.0), ray(1.0));
                    // The row's rays first: their square roots overlap instead of each stalling.
                    let rays: Vec<Ray> = (0..VIEW).map(|x| ray(pixel_center(x))).collect();
                    for (pixel, ray) in row.iter_mut().zip(&rays) {
                        *pixel = to_rgb(scene.trace(ray, &reachable, 0));
                    }
                }
            });
        }
    });
    draw_slice(scene, camera, frame);
}

/// The objects a row's rays can hit. They fan out in a plane from the first ray to the last, so
/// they miss every sphere further than r from it (planes are kept: few rays test them).
fn row_objects(scene: &Scene, first: Ray, last: Ray) -> Vec<Object> {
    let fan_normal = first.direction.cross(last.direction).normalize();
    let reachable = |(shape, _): &&Object| match *shape {
        Shape::Sphere { center, radius } => {
            (center - first.origin).dot(fan_normal).abs() < radius + EPSILON // slack for rounding
        }
        Shape::Plane { .. } => true,
    };
    scene.objects.iter().filter(reachable).copied().collect()
}

/// A colour as a 0RGB pixel, each channel clamped to [0, 1].
pub fn to_rgb(color: Vec3) -> u32 {
    let byte = |channel: f64| (channel.min(1.0) * 255.0) as u32; // `as` takes negatives to 0
    byte(color.x) << 16 | byte(color.y) << 8 | byte(color.z)
}

// The 2D slice: the plane through the eye and the screen's middle row, seen from above, x to the
// right and -z up; every 10th ray of that row to its hit, its shadow ray and its reflection.
pub const MAP_CORNER: Vec3 = vec3(-6.4, 0.0, -9.4); // the world x and z at the map's top left
pub const MAP_SCALE: f64 = 40.0; // map pixels per world unit

/// Colours the map pixel under a world point, if it is on the map.
fn plot(frame: &mut [u32], point: Vec3, color: u32) {
    let on_map = (point - MAP_CORNER) * MAP_SCALE;
    if on_map.x.min(on_map.z) >= 0.0 && on_map.x.max(on_map.z) < VIEW as f64 {
        frame[on_map.z as usize * WIDTH + VIEW + on_map.x as usize] = color;
    }
}

/// One dot a map pixel from `from` to `to`, for at most the map's diagonal (then it is off the map).
fn draw_line(frame: &mut [u32], from: Vec3, to: Vec3, color: u32) {
    let length = (to - from).length();
    for i in 0..=(length.min(18.2) * MAP_SCALE) as usize {
        plot(
            frame,
            from + (to - from) * (i as f64 / MAP_SCALE / length),
            color,
        );
    }
}

/// A dot of 5 x 5 map pixels, as five lines.
fn draw_dot(frame: &mut [u32], point: Vec3, color: u32) {
    for row in -2..=2 {
        let left = point + vec3(-2.0, 0.0, row as f64) * (1.0 / MAP_SCALE);
        draw_line(frame, left, left + vec3(4.0 / MAP_SCALE, 0.0, 0.0), color);
    }
}

/// The right half: sphere outlines, sampled rays, the screen, the light and the camera.
fn draw_slice(scene: &Scene, camera: &Camera, frame: &mut [u32]) {
    for row in frame.chunks_mut(WIDTH) {
        row[VIEW..].fill(0x202020);
    }
    let eye = camera.position;
    for (shape, material) in &scene.objects {
        if let Shape::Sphere { center, radius } = *shape {
            // It cuts the plane y = eye.y in a circle of radius² = r² - (C.y - eye.y)², drawn as
            // 64 segments (none for a NaN radius: the sphere misses the plane).
            let cut = (radius * radius - (center.y - eye.y).powi(2)).sqrt();
            let around = |i: u32| center + direction(TAU * i as f64 / 64.0, 0.0) * cut;
            for i in 0..64 {
                draw_line(frame, around(i), around(i + 1), to_rgb(material.color));
            }
        }
    }
    let screen @ [top_left, right, down] = camera.screen();
    for x in (0..VIEW).step_by(10) {
        let ray = camera.primary_ray(screen, pixel_center(x), 0.5);
        let Some((point, normal, material)) = nearest_hit(&scene.objects, &ray) else {
            draw_line(frame, eye, eye + ray.direction * 1e6, 0x808080); // a miss, to the edge of the map
            continue;
        };
        draw_line(frame, eye, point, 0xc0c040);
        draw_line(frame, scene.light, point, 0x606060);
        if material.reflectivity > 0.0 {
            let mirror = reflect(&ray, point, normal);
            let bounce = nearest_hit(&scene.objects, &mirror);
            let end = bounce.map_or(point + mirror.direction * 1e6, |hit| hit.0);
            draw_line(frame, point, end, 0x40c0ff);
        }
        draw_dot(frame, point, 0xff4040);
    }
    let middle_left = eye + top_left + down * 0.5; // the screen's middle row, over the rays
    draw_line(frame, middle_left, middle_left + right, 0xffffff);
    draw_dot(frame, scene.light, 0xffff00);
    draw_dot(frame, eye, 0xffffff);
}

// The program: the window, moved and turned by the keys at a speed × the last frame's seconds.
fn main() {
    if std::env::args().len() > 1 {
        eprintln!("usage: raytracer (no arguments: it opens a window; the keys are printed then)");
        std::process::exit(2);
    }
    let options = WindowOptions::default();
    let mut window = Window::new("raytracer", WIDTH, VIEW, options).unwrap_or_else(|error| {
        eprintln!("raytracer: cannot open a window, no display? ({error})");
        std::process::exit(1)
    });
    println!("W/S forward/back, A/D left/right, R/F up/down, arrow keys turn, Escape quits");
    let (scene, mut camera) = (Scene::default(), Camera::default());
    let mut frame = vec![0; WIDTH * VIEW];
    let mut last_frame = Instant::now();
    while window.is_open() && !window.is_key_down(Key::Escape) {
        let dt = last_frame.elapsed().as_secs_f64();
        last_frame = Instant::now();
        let held = |key| if window.is_key_down(key) { dt } else { 0.0 };
        let forward = direction(camera.yaw, camera.pitch) * (held(Key::W) - held(Key::S));
        let right = direction(camera.yaw - FRAC_PI_2, 0.0) * (held(Key::D) - held(Key::A));
        let up = vec3(0.0, held(Key::R) - held(Key::F), 0.0);
        camera.position = camera.position + (forward + right + up) * 2.0;
        camera.yaw += 1.5 * (held(Key::Left) - held(Key::Right));
        camera.pitch += 1.5 * (held(Key::Up) - held(Key::Down));
        camera.pitch = camera.pitch.clamp(-FRAC_PI_2, FRAC_PI_2); // never over the top
        render(&scene, &camera, &mut frame);
        window.set_title(&format!("raytracer - {:.0} fps", 1.0 / dt));
        if window.update_with_buffer(&frame, WIDTH, VIEW).is_err() {
            break; // the window is gone
        }
    }
}
