//! `cargo bench`: 100 frames of the default view, rendered on one core (`render` is one loop).

const FRAMES: usize = 100;
const MS_PER_SECOND: f64 = 1e3;

fn main() {
    // Cargo passes `--bench`; there is nothing to choose.
    let mut milliseconds: Vec<f64> = (0..FRAMES)
        .map(|_| program::default_frame_seconds() * MS_PER_SECOND)
        .collect();
    milliseconds.sort_by(f64::total_cmp);
    let median = milliseconds[FRAMES / 2];
    let min = milliseconds[0];
    let fps = MS_PER_SECOND / median;
    println!(
        "{FRAMES} frames of the default view: median {median:.2} ms, min {min:.2} ms, {fps:.0} fps"
    );
}

/// src/main.rs in a module, as this file has a main of its own, with the one function the bench
/// needs of it beside it (the program's items are private to the module).
#[allow(dead_code)]
mod program {
    include!("../../src/main.rs");

    /// The seconds `render` takes for a frame of the demo from the start pose.
    pub fn default_frame_seconds() -> f64 {
        let mut frame = vec![0; WIDTH * VIEW];
        let start = Instant::now();
        render(&Scene::demo(), &Camera::default(), &mut frame);
        start.elapsed().as_secs_f64()
    }
}
