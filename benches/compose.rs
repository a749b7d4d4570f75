//! Time per part of composition and principal axes, for each precision mode
//! on each stress scene of docs/accuracy.md and a 100,000-part assembly.
//!
//!     cargo bench --bench compose
//!
//! Parsing is done once, outside the timed loop: the figures are what the
//! precision mode costs. The errors that go with them come from
//! `cargo run --release --example accuracy` (docs/accuracy.md).

use divan::counter::ItemsCount;
use divan::{Bencher, black_box};
use massprop::compose::{self, Precision};
use massprop::diag::Source;
use massprop::model::Model;
#[path = "../tests/support/mod.rs"]
#[allow(dead_code)]
mod support;
use std::sync::OnceLock;
use support::{reference, scenes};

const SCENES: &[&str] = &[
    "offset 1e6",
    "offset 1e9",
    "slender 1e-6",
    "slender 1e-9",
    "flat 1e-9",
    "near-equal 1e-8",
    "mass ratio 1e12",
    "µm and mg",
    "assembly 100k",
];

fn models() -> &'static Vec<(&'static str, Model)> {
    static MODELS: OnceLock<Vec<(&'static str, Model)>> = OnceLock::new();
    MODELS.get_or_init(|| {
        let mut named = scenes::stress();
        named.push(scenes::Named {
            name: "assembly 100k",
            what: "mixed assembly",
            scene: scenes::assembly(100_000),
        });
        named
            .into_iter()
            .map(|s| {
                let text = reference::to_toml(&s.scene);
                let model = Model::parse(&Source::new(s.name, text)).expect("a valid scene");
                (s.name, model)
            })
            .collect()
    })
}

fn run(bencher: Bencher, scene: &str, precision: Precision) {
    let model = &models()
        .iter()
        .find(|(n, _)| *n == scene)
        .expect("a known scene")
        .1;
    bencher.counter(ItemsCount::new(model.count)).bench(|| {
        let body = compose::compose(black_box(&model) as &Model, precision);
        black_box(compose::principal(&body.second_moment, precision))
    });
}

#[divan::bench(args = SCENES)]
fn standard(bencher: Bencher, scene: &str) {
    run(bencher, scene, Precision::Standard);
}

#[divan::bench(args = SCENES)]
fn extended(bencher: Bencher, scene: &str) {
    run(bencher, scene, Precision::Extended);
}

fn main() {
    divan::main();
}
