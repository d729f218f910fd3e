//! The README's own claims about the demo: its two pictures, the legend's colours in them, the
//! demo balls' colours, the window's size wherever it gives it, and the size of `src/main.rs`.
//! These do not ask whether the tracer is right (the other tests do), but whether the README still
//! tells the truth: a student's own scene makes them fail, and that is fine. They are ignored by
//! `cargo test`; CI runs them with `cargo test --workspace --no-fail-fast -- --include-ignored`.
//! Each names every stale claim it finds at once, and how to bring it back.
#![allow(dead_code)] // each test file uses only part of the program
include!("../../src/main.rs"); // the program itself: its items in reach with no `pub`
#[path = "support/picture.rs"]
mod picture;
#[path = "support/tokens.rs"]
mod tokens;
#[path = "support/vision.rs"]
mod vision;

use std::fs;

/// The README's two pictures, by their paths from the repository's top: the demo from the start
/// pose, and from it looking 0.15 radians down.
fn readme_pictures() -> [(&'static str, Camera); 2] {
    let pitched = Camera {
        pitch: -0.15,
        ..Camera::default()
    };
    [
        (
            "tests/maintainers/pictures/default_frame.png",
            Camera::default(),
        ),
        ("tests/maintainers/pictures/pitched_frame.png", pitched),
    ]
}

/// A file's path from the repository's top, two folders above this package's.
fn at_top(path: &str) -> String {
    format!("{}/../../{path}", env!("CARGO_MANIFEST_DIR"))
}

fn demo_frame(camera: &Camera) -> Vec<u32> {
    let mut frame = vec![0; WIDTH * VIEW];
    render(&Scene::demo(), camera, &mut frame);
    frame
}

fn readme() -> String {
    fs::read_to_string(at_top("README.md")).expect("README.md")
}

/// The right half of a frame: the map's pixels, row by row.
fn map_of(frame: &[u32]) -> Vec<u32> {
    frame
        .chunks(WIDTH)
        .flat_map(|row| row[VIEW..].to_vec())
        .collect()
}

/// The legend's colours by name, as the README's table and the failure messages call them.
const LEGEND: [(&str, u32); 8] = [
    ("BACKGROUND", BACKGROUND),
    ("CAMERA_COLOR", CAMERA_COLOR),
    ("RAY_COLOR", RAY_COLOR),
    ("MISS_COLOR", MISS_COLOR),
    ("LIGHT_COLOR", LIGHT_COLOR),
    ("SHADOW_COLOR", SHADOW_COLOR),
    ("BLOCKED_COLOR", BLOCKED_COLOR),
    ("MIRROR_COLOR", MIRROR_COLOR),
];

/// Every stale claim a guard found, at once, or none.
fn assert_none_stale(stale: &[String]) {
    assert!(
        stale.is_empty(),
        "README.md has {} stale claim{}:\n- {}",
        stale.len(),
        if stale.len() == 1 { "" } else { "s" },
        stale.join("\n- ")
    );
}

#[test]
#[ignore = "guards the README's pictures, not the tracer: run with --include-ignored"]
fn the_readme_pictures_are_the_demos_frames() {
    let readme = readme();
    let mut stale = Vec::new();
    for (name, camera) in readme_pictures() {
        if !readme.contains(&format!("]({name})")) {
            stale.push(format!(
                "it shows no picture at {name}, where the demo's frame from its pose is \
                 (readme_pictures, in tests/maintainers/readme.rs): show it with ![...]({name})"
            ));
        }
        let path = at_top(name);
        let frame = demo_frame(&camera);
        if std::env::var_os("UPDATE_PICTURE").is_some() {
            picture::write_png(&path, &frame, WIDTH).unwrap_or_else(|error| panic!("{error}"));
            println!("wrote {name}: look at it before committing it");
            continue;
        }
        let ((width, height), stored) = match picture::read_png(&path) {
            Ok(picture) => picture,
            Err(error) => {
                stale.push(format!("the picture {name}: {error}. {UPDATE}"));
                continue;
            }
        };
        if (width, height) != (WIDTH as u32, VIEW as u32) {
            stale.push(format!(
                "the picture {name} is {width}x{height}, the frame now {WIDTH}x{VIEW}. {UPDATE}"
            ));
            continue;
        }
        let rendered = picture::rgb_bytes(&frame);
        let differing = rendered
            .chunks(3)
            .zip(stored.chunks(3))
            .filter(|(a, b)| a != b)
            .count();
        if differing > 0 {
            stale.push(format!(
                "the picture {name}: {differing} of its pixels differ from the demo's frame. \
                 {UPDATE}"
            ));
        }
    }
    assert_none_stale(&stale);
}

/// How to bring a stale picture up to date.
const UPDATE: &str = "If the change is meant, write the pictures anew with `UPDATE_PICTURE=1 cargo \
                      test -p maintainers --test readme -- --ignored` and look at them before \
                      committing them.";

/// Each size "WxH" written in a text, as its two numbers.
fn sizes_in(text: &str) -> Vec<(usize, usize)> {
    let chars: Vec<char> = text.chars().collect();
    let number = |range: &[char]| range.iter().collect::<String>().parse().ok();
    let mut sizes = Vec::new();
    for (i, &c) in chars.iter().enumerate() {
        if c != 'x' || i == 0 {
            continue;
        }
        let start = (0..i)
            .rev()
            .take_while(|&j| chars[j].is_ascii_digit())
            .last();
        let end = (i + 1..chars.len())
            .take_while(|&j| chars[j].is_ascii_digit())
            .last();
        if let (Some(start), Some(end)) = (start, end)
            && let (Some(width), Some(height)) =
                (number(&chars[start..i]), number(&chars[i + 1..=end]))
        {
            sizes.push((width, height));
        }
    }
    sizes
}

#[test]
#[ignore = "guards the README's window size, not the tracer: run with --include-ignored"]
fn each_readme_line_that_gives_the_window_size_gives_the_programs() {
    // The window is WIDTH x VIEW, each half VIEW x VIEW: a size twice as wide as high is the
    // window's, a square one a half's.
    let window = (WIDTH, VIEW);
    let half = (VIEW, VIEW);
    let mut stale = Vec::new();
    let mut given = 0;
    for (number, line) in readme().lines().enumerate() {
        for (width, height) in sizes_in(line) {
            given += 1;
            let (what, size) = if width == 2 * height {
                ("the window", window)
            } else {
                ("each half", half)
            };
            if (width, height) != size {
                stale.push(format!(
                    "README.md line {} says {width}x{height}, where {what} is now {}x{}: put \
                     {}x{} there",
                    number + 1,
                    size.0,
                    size.1,
                    size.0,
                    size.1
                ));
            }
        }
    }
    if given == 0 {
        stale.push(format!(
            "README.md gives the window's size nowhere: say it is {WIDTH}x{VIEW} pixels"
        ));
    }
    assert_none_stale(&stale);
}

/// The demo's balls, each by its centre, and their outlines' colours.
fn demo_balls() -> Vec<(String, u32)> {
    let mut balls = Vec::new();
    for (primitive, material) in Scene::demo().objects {
        if let Primitive::Sphere { center, .. } = primitive {
            let Vec3 { x, y, z } = center;
            balls.push((
                format!("the ball at ({x}, {y}, {z})"),
                outline(material.color),
            ));
        }
    }
    balls
}

/// A ball's outline on the map: its colour as a 0RGB pixel, as the map draws it.
fn outline(color: Vec3) -> u32 {
    let byte = |channel: f64| (channel.min(1.0) * 255.0) as u32;
    byte(color.x) << 16 | byte(color.y) << 8 | byte(color.z)
}

#[test]
#[ignore = "guards the README's legend, not the tracer: run with --include-ignored"]
fn every_legend_colour_and_ball_shows_from_the_readme_pictures_poses() {
    // The demo's frames from the pictures' poses: the picture test holds the pictures to them.
    let mut shown = Vec::new();
    for (_, camera) in readme_pictures() {
        shown.extend(map_of(&demo_frame(&camera)));
    }
    let mut stale = Vec::new();
    for (name, color) in LEGEND {
        if !shown.contains(&color) {
            stale.push(format!(
                "it says its two pictures show every colour of the legend, but neither shows \
                 {name} ({color:06x}): from those two poses (readme_pictures, in \
                 tests/maintainers/readme.rs) the demo, Scene::demo, no longer draws it. Change \
                 the demo so that it does, or choose other poses there and in the README and \
                 write the pictures anew."
            ));
        }
    }
    for (ball, color) in demo_balls() {
        if !shown.contains(&color) {
            stale.push(format!(
                "it says its pictures show each ball's outline, but neither shows that of {ball} \
                 in Scene::demo ({color:06x}): the pictures' planes (y = 0, and y = 0 tilted \
                 0.15 radians down) miss it. Move the ball so that they cut it, or change the \
                 README."
            ));
        }
    }
    assert_none_stale(&stale);
}

/// Colour channels tried for a suggestion: 0 to 1 in steps of 0.05.
const CHANNEL_STEPS: u32 = 20;

/// The colour nearest to `wanted` (as normal eyes see it), of those on a 0.05 grid, whose outline
/// every eye tells apart from each legend colour.
fn nearest_passing(wanted: u32) -> Option<Vec3> {
    let steps = (0..=CHANNEL_STEPS).map(|step| f64::from(step) / f64::from(CHANNEL_STEPS));
    let grid = steps.clone().flat_map(|red| {
        let steps = steps.clone();
        steps
            .clone()
            .flat_map(move |green| steps.clone().map(move |blue| vec3(red, green, blue)))
    });
    grid.filter(|&color| {
        LEGEND
            .iter()
            .all(|&(_, legend)| vision::too_alike(outline(color), legend).is_none())
    })
    .min_by(|&a, &b| {
        let apart = |color: Vec3| vision::rgb_apart(outline(color), wanted);
        apart(a).total_cmp(&apart(b))
    })
}

#[test]
#[ignore = "guards the README's colour claim for the demo's balls: run with --include-ignored"]
fn the_demo_balls_outlines_are_told_apart_from_the_legend_by_every_eye() {
    let mut stale = Vec::new();
    for (ball, outline) in demo_balls() {
        let alike: Vec<String> = LEGEND
            .iter()
            .filter_map(|&(name, color)| {
                vision::too_alike(outline, color).map(|problem| format!("{name}: {problem}"))
            })
            .collect();
        if alike.is_empty() {
            continue;
        }
        let suggestion = match nearest_passing(outline) {
            Some(color) => format!(
                "vec3({:.2}, {:.2}, {:.2}), the nearest to its colour that passes, say",
                color.x, color.y, color.z
            ),
            None => "a colour further from them".to_string(),
        };
        stale.push(format!(
            "it says each ball's outline is told apart from every colour of the legend, by every \
             eye, but {ball} in Scene::demo is too alike to {}. Give it {suggestion}, or \
             change the README.",
            alike.join("; to ")
        ));
    }
    assert_none_stale(&stale);
}

/// The README's size budget for src/main.rs.
const MOST_TOKENS: usize = 3750;
const MOST_LINES: usize = 480;

/// The number the README's size line gives right before `what`, as in "has 3,750 tokens".
fn stated(readme: &str, what: &str) -> Result<usize, String> {
    let claim = "`src/main.rs` has ";
    let start = readme.find(claim).ok_or(format!(
        "it should say \"{claim}N tokens and M non-blank lines\": put that line back"
    ))?;
    let after = &readme[start + claim.len()..];
    // Its first six words: "3,750 tokens and 480 non-blank lines".
    let words: Vec<&str> = after.split_whitespace().take(6).collect();
    let place = words.iter().position(|&word| word.starts_with(what));
    let number = place
        .and_then(|i| i.checked_sub(1))
        .and_then(|i| words.get(i));
    number
        .and_then(|n| n.replace(',', "").parse().ok())
        .ok_or(format!(
            "its line \"{claim}...\" gives no number of {what}: put it back"
        ))
}

/// A number as the README writes it: 3,750.
fn with_comma(n: usize) -> String {
    match n {
        1000.. => format!("{},{:03}", n / 1000, n % 1000),
        _ => n.to_string(),
    }
}

#[test]
#[ignore = "guards the README's size claim: run with --include-ignored"]
fn the_readme_states_the_size_of_main_rs_within_its_budget() {
    let source = fs::read_to_string(at_top("src/main.rs")).expect("src/main.rs");
    let readme = readme();
    let token_count = tokens::count_tokens(&tokens::strip_comments(&source));
    let lines = tokens::non_blank_lines(&source);
    println!("src/main.rs: {token_count} tokens, {lines} non-blank lines");
    let mut stale = Vec::new();
    let budget = format!(
        "within its budget of {} and {MOST_LINES}",
        with_comma(MOST_TOKENS)
    );
    if !readme.contains(&budget) {
        stale.push(format!(
            "it should say \"{budget}\", the budget that tests/maintainers/readme.rs (MOST_TOKENS, \
             MOST_LINES) holds src/main.rs to: bring the two together"
        ));
    }
    // The README's word after the number, the thing counted, the count and its budget.
    for (word, what, counted, most) in [
        ("tokens", "tokens", token_count, MOST_TOKENS),
        ("non-blank", "non-blank lines", lines, MOST_LINES),
    ] {
        if counted > most {
            stale.push(format!(
                "src/main.rs has {} {what}, over the budget of {}: make the code \
                 smaller (remove, never pack), or change the budget in the README and in \
                 tests/maintainers/readme.rs (MOST_TOKENS, MOST_LINES)",
                with_comma(counted),
                with_comma(most)
            ));
        }
        match stated(&readme, word) {
            Ok(said) if said == counted => {}
            Ok(said) => stale.push(format!(
                "it says src/main.rs has {} {what}; it has {} now: put {} in the README",
                with_comma(said),
                with_comma(counted),
                with_comma(counted)
            )),
            Err(problem) => stale.push(problem),
        }
    }
    assert_none_stale(&stale);
}

#[test]
#[ignore = "checks the size guard's counter: run with --include-ignored"]
fn the_token_counter_counts_as_the_rules_say() {
    // Counted by hand by the rules in support/tokens.rs.
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
