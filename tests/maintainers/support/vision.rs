//! Machinery a student need not read: how far apart two colours look to normal eyes and to the
//! two red-green colour-blind ones, for the tests that check the map's colours.

/// Two colours closer than this in RGB, to any of the three eyes, are too alike to tell apart.
pub const LEAST_APART: f64 = 64.0;
/// A sampled ray's miss differs from its hit in hue by at least this many degrees, to every eye.
pub const LEAST_HUE_APART: f64 = 60.0;

/// Protanopia and deuteranopia as Machado, Oliveira and Fernandes (2009) give them, severity 1,
/// applied to linear RGB.
const PROTANOPIA: [[f64; 3]; 3] = [
    [0.152286, 1.052583, -0.204868],
    [0.114503, 0.786281, 0.099216],
    [-0.003882, -0.048116, 1.051998],
];
const DEUTERANOPIA: [[f64; 3]; 3] = [
    [0.367322, 0.860646, -0.227968],
    [0.280085, 0.672501, 0.047413],
    [-0.011820, 0.042940, 0.968881],
];

/// A 0RGB pixel as its red, green and blue bytes.
fn channels(pixel: u32) -> [f64; 3] {
    [16, 8, 0].map(|shift| f64::from((pixel >> shift) & 255))
}

/// The sRGB curve (IEC 61966-2-1) undone: a byte to linear light from 0 to 1.
fn to_linear(level: f64) -> f64 {
    let c = level / 255.0;
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// The sRGB curve redone: linear light to a byte.
fn to_byte(linear: f64) -> f64 {
    let c = linear.clamp(0.0, 1.0);
    let encoded = if c <= 0.0031308 {
        12.92 * c
    } else {
        1.055 * c.powf(1.0 / 2.4) - 0.055
    };
    (encoded * 255.0).round()
}

fn simulate(pixel: u32, matrix: &[[f64; 3]; 3]) -> [f64; 3] {
    let linear = channels(pixel).map(to_linear);
    matrix.map(|row| to_byte(row[0] * linear[0] + row[1] * linear[1] + row[2] * linear[2]))
}

/// A colour as each eye sees it, by name.
fn as_seen(pixel: u32) -> [(&'static str, [f64; 3]); 3] {
    [
        ("normal eyes", channels(pixel)),
        ("a red-blind eye (protanopia)", simulate(pixel, &PROTANOPIA)),
        (
            "a green-blind eye (deuteranopia)",
            simulate(pixel, &DEUTERANOPIA),
        ),
    ]
}

/// How far apart two colours are in RGB, to normal eyes.
pub fn rgb_apart(a: u32, b: u32) -> f64 {
    rgb_distance(channels(a), channels(b))
}

fn rgb_distance(a: [f64; 3], b: [f64; 3]) -> f64 {
    let [dr, dg, db] = [0, 1, 2].map(|i| a[i] - b[i]);
    (dr * dr + dg * dg + db * db).sqrt()
}

/// The hue in degrees (0 red, 120 green, 240 blue), by the standard hexagon projection.
fn hue([r, g, b]: [f64; 3]) -> f64 {
    let x = r - (g + b) / 2.0;
    let y = (g - b) * 3f64.sqrt() / 2.0;
    y.atan2(x).to_degrees().rem_euclid(360.0)
}

/// Why two colours are too alike for some eye, if they are.
pub fn too_alike(a: u32, b: u32) -> Option<String> {
    as_seen(a)
        .into_iter()
        .zip(as_seen(b))
        .find_map(|((eye, seen_a), (_, seen_b))| {
            let apart = rgb_distance(seen_a, seen_b);
            (apart < LEAST_APART).then(|| {
                format!(
                    "to {eye} {a:06x} and {b:06x} are {apart:.0} apart in RGB, under {LEAST_APART}"
                )
            })
        })
}

/// Why two colours' hues are too close for some eye, if they are.
pub fn same_hue(a: u32, b: u32) -> Option<String> {
    as_seen(a).into_iter().zip(as_seen(b)).find_map(|((eye, seen_a), (_, seen_b))| {
        let turn = (hue(seen_a) - hue(seen_b)).abs();
        let apart = turn.min(360.0 - turn);
        (apart < LEAST_HUE_APART).then(|| {
            format!("to {eye} {a:06x} and {b:06x} are {apart:.0} degrees apart in hue, under {LEAST_HUE_APART}")
        })
    })
}
