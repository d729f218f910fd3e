// The assignment's checklist: `cargo test stepN` runs step N's tests, `cargo test slice` the 2D
// slice's. Each file holds one step's tests; support.rs what they share.
#![allow(dead_code, clippy::needless_update)] // the tests use part of the program; support.rs's
// `..` fills in any field you add to Material, Scene or Camera
include!("../../src/main.rs"); // the program itself: its items in reach with no `pub`

include!("support.rs"); // what the steps' tests share

mod step1;
mod step2;
mod step3;
mod step4;
mod step5;
mod step6;
mod step7;
mod step8;
mod step9;
mod the_slice;
