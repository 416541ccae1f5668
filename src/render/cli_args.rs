//! The `--render` options, flattened into the command line of `src/cli.rs`.

use std::path::PathBuf;

use clap::{Args, ValueEnum};

#[derive(Args, Debug, Clone)]
pub struct RenderArgs {
    /// Render a preview of the (single) input scene into OUT.png
    #[arg(long, value_name = "OUT.png")]
    pub render: Option<PathBuf>,
    /// Image size of the preview
    #[arg(long, value_name = "WxH", default_value = "800x600", value_parser = parse_size)]
    pub size: ImageSize,
    /// Speed/accuracy trade of the preview
    #[arg(long, value_enum, default_value_t = Quality::Balanced)]
    pub quality: Quality,
    /// The Viewpoint to render from: `auto` (the first Viewpoint, else a framing of the
    /// scene's bounds), `browser` (the first Viewpoint, else the X3D default Viewpoint at
    /// 0 0 10, as a browser binds) or the DEF name of a Viewpoint
    #[arg(long, value_name = "auto|browser|DEF", default_value = "auto")]
    pub camera: String,
    /// The X3D island of an HTML page to render, 1-based (a page may hold several
    /// `<x3d>` elements; the report names each when there are several)
    #[arg(long, value_name = "N", default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..))]
    pub island: u32,
}

#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct ImageSize {
    pub width: u32,
    pub height: u32,
}

/// The largest side accepted: a preview, not a poster (and a bound on memory).
pub const MAX_SIDE: u32 = 8192;

impl std::str::FromStr for ImageSize {
    type Err = String;

    fn from_str(text: &str) -> Result<ImageSize, String> {
        parse_size(text)
    }
}

fn parse_size(text: &str) -> Result<ImageSize, String> {
    let (w, h) = text
        .split_once(['x', 'X'])
        .ok_or_else(|| format!("`{text}` is not WxH, e.g. 800x600"))?;
    let side = |s: &str| -> Result<u32, String> {
        match s.trim().parse::<u32>() {
            Ok(v) if (1..=MAX_SIDE).contains(&v) => Ok(v),
            _ => Err(format!("`{s}` is not a side length from 1 to {MAX_SIDE}")),
        }
    };
    Ok(ImageSize {
        width: side(w)?,
        height: side(h)?,
    })
}

/// The speed/accuracy presets: `fast` lights per vertex (Gouraud shading, 17.2.2.8) with
/// one sample per pixel; `balanced` lights per pixel (Phong shading, every material
/// texture) with 4× multisampling; `accurate` also renders at twice the size and averages
/// down (16 samples per pixel).
#[derive(Copy, Clone, Debug, PartialEq, Eq, ValueEnum)]
pub enum Quality {
    Fast,
    Balanced,
    Accurate,
}

#[cfg(feature = "render")]
impl Quality {
    pub fn settings(self) -> super::Settings {
        use super::{Settings, Shading};
        match self {
            Quality::Fast => Settings {
                shading: Shading::Gouraud,
                msaa_samples: 1,
                supersampling: 1,
            },
            Quality::Balanced => Settings {
                shading: Shading::Phong,
                msaa_samples: 4,
                supersampling: 1,
            },
            Quality::Accurate => Settings {
                shading: Shading::Phong,
                msaa_samples: 4,
                supersampling: 2,
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_parse_and_bounds_hold() {
        assert_eq!(
            parse_size("640x480"),
            Ok(ImageSize {
                width: 640,
                height: 480
            })
        );
        assert!(parse_size("0x10").is_err());
        assert!(parse_size("10").is_err());
        assert!(parse_size("99999x10").is_err());
        assert!(parse_size("-1x10").is_err());
    }
}
