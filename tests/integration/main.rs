//! massprop's integration tests, in one binary: each extra test binary is
//! another link on a 2-core machine.

mod alarms;
mod arrays;
mod auto;
mod bounded;
mod bounds;
mod budget;
mod capsule;
mod cases;
mod channels;
mod check;
mod ci;
mod cli;
mod colour;
mod common;
mod copies_walk;
mod cost;
mod depth;
mod diff;
mod docs;
mod docs_run;
mod drawing_legible;
mod ellipsoid;
mod envelope;
mod exact;
mod expect_axes;
mod explain;
mod files;
mod frames;
mod honesty;
mod hostile;
mod hostile_round_two;
mod invariants;
mod json_types;
mod keys_docs;
mod layers;
mod leftovers;
mod library;
mod limits;
mod mesh_classes;
mod meshes;
mod new_shapes;
mod oracle;
mod package;
mod params;
mod physics;
mod pipes;
mod placed_bodies;
mod plausible;
mod reference;
mod render;
mod report_keys;
mod robot_body;
mod robots;
mod robots_hostile;
mod schema;
mod shell;
mod short_report;
mod stress;
mod uncertainty;
mod unit_bounds;
// Shared with the benchmark and an example, each using a part.
#[path = "../support/mod.rs"]
#[allow(dead_code)]
mod support;
mod walk;
