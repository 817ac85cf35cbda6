//! `zieglerlab presets`: every preset with each parameter, its unit and its range.

use std::io::Write;

use anyhow::Result;
use serde_json::json;

use zieglerlab::model::{KEYS, PRESETS};

#[derive(clap::Args, Debug)]
pub struct Args {
    #[arg(long)]
    json: bool,
}

pub fn run(args: &Args, out: &mut impl Write) -> Result<()> {
    if args.json {
        let presets: Vec<_> = PRESETS
            .iter()
            .map(|preset| {
                let model = preset.model();
                let parameters: Vec<_> = KEYS
                    .iter()
                    .filter(|key| key.applies_to(&model))
                    .map(|key| {
                        json!({
                            "key": key.key.name(),
                            "value": key.get(&model),
                            "unit": key.unit,
                            "range": key.range,
                            "group": key.is_group,
                            "description": key.description,
                        })
                    })
                    .collect();
                json!({"name": preset.id.name(), "source": preset.source, "description": preset.description, "parameters": parameters})
            })
            .collect();
        writeln!(out, "{}", serde_json::to_string_pretty(&presets)?)?;
        return Ok(());
    }
    for preset in &PRESETS {
        let model = preset.model();
        writeln!(
            out,
            "{} ({})\n  {}",
            preset.id.name(),
            preset.source,
            preset.description
        )?;
        for key in KEYS.iter().filter(|key| key.applies_to(&model)) {
            let unit = if key.unit.is_empty() { "-" } else { key.unit };
            writeln!(
                out,
                "  {:<6} {:>12} {:<10} {:<12} {}",
                key.key.name(),
                format!("{:.6}", key.get(&model))
                    .trim_end_matches('0')
                    .trim_end_matches('.'),
                unit,
                key.range,
                key.description
            )?;
        }
        writeln!(out)?;
    }
    Ok(())
}
