//! The README's own claims about the demo: its two pictures, the legend's colours in them, the
//! demo balls' colours, and the size of `src/main.rs`. These do not ask whether the tracer is right
//! (the other tests do), but whether the README still tells the truth: a student's own scene makes
//! them fail, and that is fine. They are ignored by `cargo test`; CI runs them with
//! `cargo test --no-fail-fast -- --include-ignored`, and each failure says what to bring up to
//! date.
#[allow(dead_code)]
#[path = "../src/main.rs"]
mod raytracer;
#[allow(dead_code)]
#[path = "support/scenes.rs"]
mod scenes;
#[allow(dead_code)]
#[path = "support/tokens.rs"]
mod tokens;
#[allow(dead_code)]
#[path = "support/vision.rs"]
mod vision;

use raytracer::*;
use scenes::{LEGEND, map_of};
use std::fs::{self, File};
use std::io::BufReader;

/// The README's two pictures: the demo from the start pose, and from it looking 0.15 radians down.
fn readme_pictures() -> [(&'static str, Camera); 2] {
    let pitched = Camera {
        pitch: -0.15,
        ..Camera::default()
    };
    [
        ("tests/default_frame.png", Camera::default()),
        ("tests/pitched_frame.png", pitched),
    ]
}

fn demo_frame(camera: &Camera) -> Vec<u32> {
    let mut frame = vec![0; WIDTH * VIEW];
    render(&Scene::default(), camera, &mut frame);
    frame
}

/// A frame of 0RGB pixels as 8-bit RGB bytes, row after row, as a PNG holds it.
fn rgb_bytes(frame: &[u32]) -> Vec<u8> {
    let bytes = |pixel: u32| [(pixel >> 16) as u8, (pixel >> 8) as u8, pixel as u8];
    frame.iter().flat_map(|&pixel| bytes(pixel)).collect()
}

fn write_png(path: &str, rgb: &[u8]) {
    let file = File::create(path).expect("the picture can be written");
    let mut encoder = png::Encoder::new(file, WIDTH as u32, VIEW as u32);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header().expect("a PNG header");
    writer.write_image_data(rgb).expect("the picture's pixels");
}

/// A PNG's size and its pixels as 8-bit RGB bytes.
fn read_png(path: &str) -> ((u32, u32), Vec<u8>) {
    let file = File::open(path)
        .unwrap_or_else(|_| panic!("the README's picture {path} is missing. {UPDATE}"));
    let mut reader = png::Decoder::new(BufReader::new(file))
        .read_info()
        .expect("a PNG");
    let info = reader.info();
    let size = (info.width, info.height);
    assert!(
        info.color_type == png::ColorType::Rgb && info.bit_depth == png::BitDepth::Eight,
        "{path} is not an 8-bit RGB picture, as UPDATE_PICTURE=1 writes them"
    );
    let mut rgb = vec![
        0;
        reader
            .output_buffer_size()
            .expect("a picture that fits in memory")
    ];
    reader.next_frame(&mut rgb).expect("the picture's pixels");
    (size, rgb)
}

#[test]
#[ignore = "guards the README's pictures, not the tracer: run with --include-ignored"]
fn the_readme_pictures_are_the_demos_frames() {
    for (name, camera) in readme_pictures() {
        let path = format!("{}/{name}", env!("CARGO_MANIFEST_DIR"));
        let rendered = rgb_bytes(&demo_frame(&camera));
        if std::env::var_os("UPDATE_PICTURE").is_some() {
            write_png(&path, &rendered);
            println!("wrote {name}: look at it before committing it");
            continue;
        }
        let ((width, height), stored) = read_png(&path);
        assert!(
            (width, height) == (WIDTH as u32, VIEW as u32),
            "The README's picture {name} and the window size it gives are stale: the picture is \
             {width} x {height}, the frame now {WIDTH} x {VIEW}. Put the new size in the README. \
             {UPDATE}"
        );
        let differing = rendered
            .chunks(3)
            .zip(stored.chunks(3))
            .filter(|(a, b)| a != b)
            .count();
        assert!(
            differing == 0,
            "The README's picture {name} is stale: {differing} of its pixels differ from the \
             demo's frame. {UPDATE}"
        );
    }
}

/// How to bring a stale picture up to date.
const UPDATE: &str = "If the change is meant, write the pictures anew with `UPDATE_PICTURE=1 cargo \
                      test --test readme -- --ignored` and look at them before committing them.";

/// The demo's balls, each by its centre, and their outlines' colours.
fn demo_balls() -> Vec<(String, u32)> {
    let byte = |channel: f64| (channel.min(1.0) * 255.0) as u32;
    let mut balls = Vec::new();
    for (primitive, material) in Scene::default().objects {
        if let Primitive::Sphere { center, .. } = primitive {
            let ball = format!("the ball at ({}, {}, {})", center.x, center.y, center.z);
            let Vec3 { x, y, z } = material.color;
            balls.push((ball, byte(x) << 16 | byte(y) << 8 | byte(z)));
        }
    }
    balls
}

#[test]
#[ignore = "guards the README's legend, not the tracer: run with --include-ignored"]
fn every_legend_colour_and_ball_shows_from_the_readme_pictures_poses() {
    // The demo's frames from the pictures' poses: the picture test holds the pictures to them.
    let mut shown = Vec::new();
    for (_, camera) in readme_pictures() {
        shown.extend(map_of(&demo_frame(&camera)));
    }
    for (name, color) in LEGEND {
        assert!(
            shown.contains(&color),
            "The README says its two pictures show every colour of the legend, but neither \
             shows {name} ({color:06x}): from those two poses (readme_pictures, in \
             tests/readme.rs) the demo, Scene::default, no longer draws it. Change the demo so \
             that it does, or choose other poses there and in the README and write the pictures \
             anew."
        );
    }
    for (ball, color) in demo_balls() {
        assert!(
            shown.contains(&color),
            "The README says its pictures show each ball's outline, but neither shows that of \
             {ball} in Scene::default ({color:06x}): the pictures' planes (y = 0, and y = 0 \
             tilted 0.15 radians down) miss it. Move the ball so that they cut it, or change the \
             README."
        );
    }
}

#[test]
#[ignore = "guards the README's colour claim for the demo's balls: run with --include-ignored"]
fn the_demo_balls_outlines_are_told_apart_from_the_legend_by_every_eye() {
    for (ball, outline) in demo_balls() {
        for (name, color) in LEGEND {
            if let Some(problem) = vision::too_alike(outline, color) {
                panic!(
                    "The README says each ball's outline is told apart from every colour of the \
                     legend, by every eye; {ball} in Scene::default and {name} are too alike: \
                     {problem}. Give that ball a colour further from {name}, or change the \
                     README."
                );
            }
        }
    }
}

/// The README's size budget for src/main.rs.
const MOST_TOKENS: usize = 3700;
const MOST_LINES: usize = 475;

/// The number the README's Size section gives right before `what`, as in "has 3,700 tokens".
fn stated(readme: &str, what: &str) -> usize {
    let claim = "`src/main.rs` has ";
    let start = readme
        .find(claim)
        .expect("the README's Size section should say \"`src/main.rs` has ...\": put it back");
    let after = &readme[start + claim.len()..];
    // Its first six words: "3,700 tokens and 472 non-blank lines".
    let words: Vec<&str> = after.split_whitespace().take(6).collect();
    let place = words.iter().position(|&word| word.starts_with(what));
    let number = place
        .and_then(|i| i.checked_sub(1))
        .and_then(|i| words.get(i));
    number
        .and_then(|n| n.replace(',', "").parse().ok())
        .unwrap_or_else(|| {
            panic!("the README's Size section gives no number of {what}: put it back")
        })
}

#[test]
#[ignore = "guards the README's size claim: run with --include-ignored"]
fn the_readme_states_the_size_of_main_rs_within_its_budget() {
    let root = env!("CARGO_MANIFEST_DIR");
    let source = fs::read_to_string(format!("{root}/src/main.rs")).expect("src/main.rs");
    let readme = fs::read_to_string(format!("{root}/README.md")).expect("README.md");
    let token_count = tokens::count_tokens(&tokens::strip_comments(&source));
    let lines = tokens::non_blank_lines(&source);
    println!("src/main.rs: {token_count} tokens, {lines} non-blank lines");
    let budget = format!(
        "within its budget of {},{:03} and {MOST_LINES}",
        MOST_TOKENS / 1000,
        MOST_TOKENS % 1000
    );
    assert!(
        readme.contains(&budget),
        "The README's Size section should say \"{budget}\", the budget that tests/readme.rs \
         (MOST_TOKENS, MOST_LINES) holds src/main.rs to: bring the two together."
    );
    // The README's word after the number, the thing counted, the count and its budget.
    for (word, what, counted, most) in [
        ("tokens", "tokens", token_count, MOST_TOKENS),
        ("non-blank", "non-blank lines", lines, MOST_LINES),
    ] {
        assert!(
            counted <= most,
            "src/main.rs has {counted} {what}, over the budget of {most} that the README states: \
             the README's claim that it is within its budget no longer holds. Make the code \
             smaller (remove, never pack), or change the budget in the README and in \
             tests/readme.rs (MOST_TOKENS, MOST_LINES)."
        );
        let said = stated(&readme, word);
        assert!(
            said == counted,
            "The README's Size section says src/main.rs has {said} {what}; it has {counted} now: \
             put {counted} in the README."
        );
    }
}

#[test]
#[ignore = "checks the size guard's counter: run with --include-ignored"]
fn the_token_counter_counts_as_the_rules_say() {
    // Counted by hand by the rules in tests/support/tokens.rs.
    let cases = [
        // let x = a :: b ( 1.5e-3 , 'c' , "s\"t" ) ;
        ("let x = a::b(1.5e-3, 'c', \"s\\\"t\"); // gone", 14),
        // fn f < 'a > ( v : & 'a [ u8 ] ) -> u8 { v [ 0 ] }
        ("fn f<'a>(v: &'a [u8]) -> u8 { v[0] }", 22),
        // x <<= 0x1f_u8 >> 2 ..= 3 && y .0
        ("x <<= 0x1f_u8 >> 2..=3 /* gone */ && y.0", 10),
        // r#"a "# b '\n' 1_000.25f64
        ("r#\"a \"# b '\\n' 1_000.25f64 ", 4),
    ];
    for (code, expected) in cases {
        let counted = tokens::count_tokens(&tokens::strip_comments(code));
        assert!(
            counted == expected,
            "the counter counts {counted} tokens in `{code}`, not {expected}"
        );
    }
    let lines = tokens::non_blank_lines("a\n\n  \n b // c\n");
    assert!(
        lines == 2,
        "the counter counts {lines} non-blank lines in a text of 2"
    );
}
