//! The GPU part: draws a [`DrawList`] offscreen with wgpu and reads the image back. It
//! trusts the draw list's guarantees (see [`super::draw_list`]) and knows nothing of X3D.

mod environment;
mod frame;
mod pipelines;
mod reach;
mod resources;
mod uniforms;

use super::draw_list::DrawList;

/// Why no image could be made.
#[derive(Debug, thiserror::Error)]
pub enum GpuError {
    #[error(
        "no graphics adapter found (not even a software one); install Mesa's software \
         drivers, e.g. on Debian/Ubuntu `apt-get install mesa-vulkan-drivers` (lavapipe, \
         Vulkan) or `libegl1 libgl1-mesa-dri` (llvmpipe, OpenGL)"
    )]
    NoAdapter,
    #[error("the graphics device could not be opened: {0}")]
    Device(String),
    #[error("the graphics device failed while rendering: {0}")]
    Failed(String),
}

/// Where the lighting equations are evaluated (17.2.2.8).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Shading {
    /// Per vertex, the main texture applied per fragment.
    Gouraud,
    /// Per fragment, with every material texture.
    Phong,
}

/// How an image is made: the speed/accuracy trade of the quality presets.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub struct Settings {
    pub shading: Shading,
    /// Multisampling: 1 or 4 (the counts every adapter supports).
    pub msaa_samples: u32,
    /// The image is drawn this many times larger on each side and averaged down.
    pub supersampling: u32,
}

/// Renders the draw list into a `width` × `height` RGBA image (rows from the top) on a
/// device opened for it. The list is consumed: each mesh's arrays are freed once they are
/// on the GPU.
pub fn render(
    list: DrawList,
    width: u32,
    height: u32,
    settings: Settings,
) -> Result<image::RgbaImage, GpuError> {
    Gpu::open()?.render(list, width, height, settings)
}

/// An open graphics device, for drawing several images without opening one each time.
pub struct Gpu {
    device: wgpu::Device,
    queue: wgpu::Queue,
}

impl Gpu {
    /// Opens a device on any adapter, software ones included (`WGPU_BACKEND` chooses).
    pub fn open() -> Result<Gpu, GpuError> {
        let (device, queue) = pollster::block_on(open_device())?;
        Ok(Gpu { device, queue })
    }

    /// Renders the draw list into a `width` × `height` RGBA image (rows from the top),
    /// consuming it.
    pub fn render(
        &self,
        list: DrawList,
        width: u32,
        height: u32,
        settings: Settings,
    ) -> Result<image::RgbaImage, GpuError> {
        pollster::block_on(render_on(
            &self.device,
            &self.queue,
            list,
            width,
            height,
            settings,
        ))
    }
}

async fn render_on(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    list: DrawList,
    width: u32,
    height: u32,
    settings: Settings,
) -> Result<image::RgbaImage, GpuError> {
    let max_side = device.limits().max_texture_dimension_2d;
    if width > max_side || height > max_side {
        return Err(GpuError::Device(format!(
            "the image is larger than the device's largest texture ({max_side} pixels)"
        )));
    }
    // Supersampling shrinks until the enlarged image fits the device.
    let mut scale = settings.supersampling.max(1);
    while scale > 1 && (width * scale > max_side || height * scale > max_side) {
        scale -= 1;
    }
    let (target_width, target_height) = (width * scale, height * scale);
    // Device errors become a GpuError rather than wgpu's default panic; scopes pop in
    // reverse order.
    let scopes = [
        wgpu::ErrorFilter::Validation,
        wgpu::ErrorFilter::OutOfMemory,
        wgpu::ErrorFilter::Internal,
    ]
    .map(|filter| device.push_error_scope(filter));
    let drawn = frame::draw(
        device,
        queue,
        list,
        frame::Target {
            width: target_width,
            height: target_height,
            scale,
            samples: settings.msaa_samples,
            shading: settings.shading,
            pass_indices: frame::PASS_INDICES,
            tile_samples: frame::TILE_SAMPLES,
        },
    )
    .await;
    for scope in scopes.into_iter().rev() {
        if let Some(error) = scope.pop().await {
            return Err(GpuError::Failed(error.to_string()));
        }
    }
    drawn
}

/// A device on any adapter (see `find_adapter`); public for tests that run the WGSL.
pub async fn open_device() -> Result<(wgpu::Device, wgpu::Queue), GpuError> {
    let adapter = find_adapter().await.ok_or(GpuError::NoAdapter)?;
    adapter
        .request_device(&wgpu::DeviceDescriptor {
            label: Some("x3dcheck"),
            required_limits: wgpu::Limits::downlevel_defaults().using_resolution(adapter.limits()),
            // Vertex and index buffers written in place (see `resources::buffer`).
            required_features: adapter.features() & wgpu::Features::MAPPABLE_PRIMARY_BUFFERS,
            ..Default::default()
        })
        .await
        .map_err(|e| GpuError::Device(e.to_string()))
}

/// Any adapter, software ones included. Vulkan first (lavapipe is the most complete
/// software driver, and probing GL/EGL without a display prints warnings), then the
/// others; `WGPU_BACKEND` overrides the choice.
pub(super) async fn find_adapter() -> Option<wgpu::Adapter> {
    let from_env = wgpu::Backends::from_env();
    let attempts = match from_env {
        Some(backends) => vec![backends],
        None => vec![
            wgpu::Backends::VULKAN | wgpu::Backends::METAL | wgpu::Backends::DX12,
            wgpu::Backends::GL,
        ],
    };
    for backends in attempts {
        let mut descriptor = wgpu::InstanceDescriptor::new_without_display_handle();
        descriptor.backends = backends;
        let instance = wgpu::Instance::new(descriptor);
        if let Ok(adapter) = instance
            .request_adapter(&wgpu::RequestAdapterOptions::default())
            .await
        {
            return Some(adapter);
        }
        if let Some(adapter) = instance
            .enumerate_adapters(backends)
            .await
            .into_iter()
            .next()
        {
            return Some(adapter);
        }
    }
    None
}
