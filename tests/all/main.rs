//! The integration tests as one binary: each module was a test file of its own, and each
//! file built its own binary linking the whole crate again. Run one module with
//! `cargo test --release --test all MODULE::`.

mod common;
mod support;

mod audit;
mod balancing;
mod batch;
mod bench;
mod blobs;
mod blocking;
mod blocking_region;
mod blocking_scenes;
mod cam;
mod cam_breaks;
mod cam_diagrams;
mod cam_oracle;
mod cam_sheets;
mod cam_special;
mod cli;
mod dimension_texts;
mod dynamics;
mod engine;
mod forces;
mod friction;
mod friction_follower;
mod fuzz_regressions;
mod gears;
mod guide_carrier;
mod hand_reading;
mod hard_cases;
mod hostile;
mod hostile_audit;
mod hostile_batch;
mod kinematics;
mod languages;
mod mechanism_limits;
mod messages;
mod mutations;
mod note;
mod note_errata;
mod note_form;
mod note_genres;
mod note_language;
mod note_worked_kinematics;
mod note_worked_machines;
mod output;
mod plan_lines;
mod plate_demo;
mod plate_rules;
mod plates;
mod seed_shaper;
mod session;
mod sheet_room;
mod sheets;
mod trains;
