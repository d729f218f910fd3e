//! `cargo bench`: 100 frames of the default view, rendered on one core (`render` is one loop).
#[allow(dead_code)]
#[path = "../../src/main.rs"]
mod raytracer;

use raytracer::*;
use std::time::Instant;

const FRAMES: usize = 100;
const MS_PER_SECOND: f64 = 1e3;

fn main() {
    // Cargo passes `--bench`; there is nothing to choose.
    let scene = Scene::default();
    let camera = Camera::default();
    let mut frame = vec![0; WIDTH * VIEW];
    let mut milliseconds: Vec<f64> = (0..FRAMES)
        .map(|_| {
            let start = Instant::now();
            render(&scene, &camera, &mut frame);
            start.elapsed().as_secs_f64() * MS_PER_SECOND
        })
        .collect();
    milliseconds.sort_by(f64::total_cmp);
    let median = milliseconds[FRAMES / 2];
    let min = milliseconds[0];
    let fps = MS_PER_SECOND / median;
    println!(
        "{FRAMES} frames of the default view: median {median:.2} ms, min {min:.2} ms, {fps:.0} fps"
    );
}
