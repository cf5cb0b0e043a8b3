//! `inspect`: what is in a glTF file, and where its vertices are at a time of a clip.
//!
//! - `inspect <file.gltf|.glb>` lists nodes, meshes, materials, skins and clips (with
//!   durations in seconds).
//! - `inspect <file> [--clip <name|index> --time <seconds>] --dump-vertices out.bin` writes
//!   the world-space position of every vertex after node transforms, morphing and skinning,
//!   as little-endian float32 x y z: primitives ordered by mesh index, then node index (a mesh
//!   used by several nodes appears once per node), then primitive index, nodes of the default
//!   scene only (the layout of `shared/external/animation-reference`). Without `--clip`, the
//!   rest pose. Times are float64 seconds; past the clip's end the last keys hold.

mod dump;
mod list;

use std::path::PathBuf;

use anyhow::{Context, Result, bail};
use clap::Parser;

/// Lists a glTF file's contents, or dumps its animated vertex positions.
#[derive(Parser, Debug)]
#[command(name = "inspect", version, about)]
struct Args {
    /// The .gltf or .glb file.
    file: PathBuf,
    /// The clip to evaluate: its name, or its index.
    #[arg(long)]
    clip: Option<String>,
    /// Seconds into the clip (default 0).
    #[arg(long)]
    time: Option<f64>,
    /// Write world-space vertex positions (little-endian float32 xyz) to this file.
    #[arg(long, value_name = "OUT.bin")]
    dump_vertices: Option<PathBuf>,
}

fn main() -> Result<()> {
    let args = Args::parse();
    let model = candela::sim::animation::load_animation_file(&args.file)
        .with_context(|| format!("loading {}", args.file.display()))?;
    if args.time.is_some() && args.clip.is_none() {
        bail!("--time needs --clip");
    }
    if let Some(time) = args.time
        && !time.is_finite()
    {
        bail!("--time must be a finite number of seconds, got {time}");
    }
    match &args.dump_vertices {
        Some(out) => {
            let clip = args
                .clip
                .as_deref()
                .map(|c| model.find_clip(c))
                .transpose()?;
            let written = dump::write(&model, clip, args.time.unwrap_or(0.0), out)?;
            println!("wrote {written} vertices to {}", out.display());
        }
        None => {
            if args.clip.is_some() {
                bail!("--clip and --time are used with --dump-vertices");
            }
            list::print(&args.file, &model);
        }
    }
    Ok(())
}
