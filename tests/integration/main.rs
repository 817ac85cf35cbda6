//! The integration tests, one module per topic, in one crate (one link of
//! the app, wgpu and rapier instead of one per topic).

mod app_input;
mod app_lessons;
mod app_logic;
mod app_tools;
mod as_printed;
mod bad_input;
mod chain_engines;
mod chains;
mod cli;
mod cli_files;
mod closed_form_loads;
mod common;
mod damped_ziegler;
mod eigen_solver;
mod energy_balance;
mod external_damping;
mod figures;
mod jacobian;
mod lecture_pace;
mod locus_tracking;
mod locus_view;
mod map_panel;
mod massless_roller;
mod partial_follower;
mod properties;
mod ramp;
mod sim_energy;
mod sim_engines;
mod sim_identification;
mod sim_large_amplitude;
mod snapshots;
mod stability_map;
mod status_card;
mod stored_settings;
mod zero_root;
