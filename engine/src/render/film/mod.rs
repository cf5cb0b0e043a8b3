//! The film: accumulated samples, the converged image, tonemapping and image files.

mod accumulate;
mod image_io;
mod tonemap;

pub use accumulate::Film;
pub use image_io::{read_exr, write_exr, write_png, ImageIoError};
pub use tonemap::{linear_to_srgb8, TonemapSettings};
