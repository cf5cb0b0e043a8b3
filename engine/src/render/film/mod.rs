//! The film: accumulated samples, the converged image, tonemapping and image files.

mod accumulate;
mod converge;
mod downsample;
mod image_io;
mod tonemap;

pub use accumulate::Film;
pub use converge::{Converge, ConvergePolicy};
pub use downsample::box_average;
pub use image_io::{ImageIoError, read_exr, write_exr, write_png, write_png_rgb8};
pub use tonemap::{TonemapSettings, linear_to_srgb8};
