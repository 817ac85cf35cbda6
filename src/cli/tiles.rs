//! The headless renderer of the command line's pictures: wgpu, drawing a
//! picture of any accepted size in tiles no larger than [`TILE_PX`], each
//! waited for on its own, so that a large picture on a busy machine's CPU
//! renderer never runs into one long wait (wgpu's GL backend on Mesa's
//! llvmpipe took over 10 s for a whole 8192x4096 picture).

use std::sync::mpsc::channel;
use std::time::Duration;

use eframe::egui;
use eframe::egui_wgpu::{self, RenderState, ScreenDescriptor, wgpu};
use egui::epaint::{ClippedPrimitive, Primitive};
use image::RgbaImage;

/// The largest tile's side, in pixels.
pub const TILE_PX: u32 = 1024;

/// How long one tile may take to draw and read back. A 1024x1024 tile
/// takes a fraction of a second on Mesa's llvmpipe even with every core
/// busy; this only guards against a lost device that never answers.
const TILE_WAIT: Duration = Duration::from_mins(2);

/// Draws egui's output tile by tile through one wgpu device.
pub struct TiledRenderer {
    state: RenderState,
}

impl TiledRenderer {
    /// A renderer on the adapter egui's test harness would choose (a CPU
    /// one first). Panics when there is none, as the harness does; the
    /// caller turns that into one clear error.
    pub fn new() -> Self {
        Self {
            state: egui_kittest::wgpu::create_render_state(
                egui_kittest::wgpu::default_wgpu_setup(),
                egui_wgpu::RendererOptions::PREDICTABLE,
            ),
        }
    }

    /// One tile: the primitives moved by `offset_px` (whole pixels) and drawn
    /// into a `size_px` texture, read back.
    fn tile(
        &self,
        primitives: &[ClippedPrimitive],
        pixels_per_point: f32,
        offset_px: [u32; 2],
        size_px: [u32; 2],
    ) -> Result<RgbaImage, String> {
        let device = &self.state.device;
        let queue = &self.state.queue;
        #[expect(
            clippy::cast_precision_loss,
            reason = "offsets are at most 8192 pixels: exact in f32"
        )]
        let shift = -egui::vec2(offset_px[0] as f32, offset_px[1] as f32) / pixels_per_point;
        let moved = if offset_px == [0, 0] {
            primitives.to_vec()
        } else {
            primitives.iter().map(|p| moved_by(p, shift)).collect()
        };
        let screen = ScreenDescriptor {
            size_in_pixels: size_px,
            pixels_per_point,
        };
        let mut renderer = self.state.renderer.write();
        let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("tile"),
        });
        let user_buffers = renderer.update_buffers(device, queue, &mut encoder, &moved, &screen);
        let texture = device.create_texture(&wgpu::TextureDescriptor {
            label: Some("tile"),
            size: wgpu::Extent3d {
                width: size_px[0],
                height: size_px[1],
                depth_or_array_layers: 1,
            },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: self.state.target_format,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
            view_formats: &[],
        });
        let view = texture.create_view(&wgpu::TextureViewDescriptor::default());
        {
            let mut pass = encoder
                .begin_render_pass(&wgpu::RenderPassDescriptor {
                    label: Some("tile"),
                    color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                        view: &view,
                        resolve_target: None,
                        ops: wgpu::Operations {
                            load: wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT),
                            store: wgpu::StoreOp::Store,
                        },
                        depth_slice: None,
                    })],
                    ..Default::default()
                })
                .forget_lifetime();
            renderer.render(&mut pass, &moved, &screen);
        }
        // Rows of the read-back buffer are padded to wgpu's alignment.
        let row_bytes = 4 * size_px[0];
        let padded_row_bytes = row_bytes.div_ceil(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT)
            * wgpu::COPY_BYTES_PER_ROW_ALIGNMENT;
        let buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("tile read-back"),
            size: u64::from(padded_row_bytes) * u64::from(size_px[1]),
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        encoder.copy_texture_to_buffer(
            texture.as_image_copy(),
            wgpu::TexelCopyBufferInfo {
                buffer: &buffer,
                layout: wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(padded_row_bytes),
                    rows_per_image: None,
                },
            },
            texture.size(),
        );
        let submission = queue.submit(user_buffers.into_iter().chain([encoder.finish()]));
        let slice = buffer.slice(..);
        let (sender, receiver) = channel();
        slice.map_async(wgpu::MapMode::Read, move |result| drop(sender.send(result)));
        device
            .poll(wgpu::PollType::Wait {
                submission_index: Some(submission),
                timeout: Some(TILE_WAIT),
            })
            .map_err(|error| format!("PollError: {error}"))?;
        receiver
            .recv()
            .map_err(|_| "the tile was never mapped".to_owned())?
            .map_err(|error| format!("reading the tile back: {error}"))?;
        let mapped = slice
            .get_mapped_range()
            .map_err(|error| format!("reading the tile back: {error}"))?;
        let pixels: Vec<u8> = mapped
            .chunks_exact(padded_row_bytes as usize)
            .flat_map(|row| &row[..row_bytes as usize])
            .copied()
            .collect();
        RgbaImage::from_raw(size_px[0], size_px[1], pixels)
            .ok_or_else(|| "a tile of the wrong size".to_owned())
    }
}

/// `primitive` moved by `shift` points, its clip rectangle with it.
fn moved_by(primitive: &ClippedPrimitive, shift: egui::Vec2) -> ClippedPrimitive {
    let primitive_moved = match &primitive.primitive {
        Primitive::Mesh(mesh) => {
            let mut mesh = mesh.clone();
            mesh.translate(shift);
            Primitive::Mesh(mesh)
        }
        Primitive::Callback(callback) => {
            let mut callback = callback.clone();
            callback.rect = callback.rect.translate(shift);
            Primitive::Callback(callback)
        }
    };
    ClippedPrimitive {
        clip_rect: primitive.clip_rect.translate(shift),
        primitive: primitive_moved,
    }
}

impl egui_kittest::TestRenderer for TiledRenderer {
    fn handle_delta(&mut self, delta: &mut egui::TexturesDelta) {
        let mut renderer = self.state.renderer.write();
        for (id, images) in std::mem::take(&mut delta.set) {
            for image in images {
                renderer.update_texture(&self.state.device, &self.state.queue, id, &image);
            }
        }
        for id in std::mem::take(&mut delta.free) {
            renderer.free_texture(&id);
        }
    }

    fn render(
        &mut self,
        ctx: &egui::Context,
        output: &egui::FullOutput,
    ) -> Result<RgbaImage, String> {
        let pixels_per_point = ctx.pixels_per_point();
        let size = ctx.content_rect().size() * pixels_per_point;
        #[expect(
            clippy::cast_possible_truncation,
            clippy::cast_sign_loss,
            reason = "a picture's size in pixels, at most 8192 each way"
        )]
        let (width, height) = (size.x.round() as u32, size.y.round() as u32);
        let primitives = ctx.tessellate(output.shapes.clone(), pixels_per_point);
        let mut picture = RgbaImage::new(width, height);
        for y in (0..height).step_by(TILE_PX as usize) {
            for x in (0..width).step_by(TILE_PX as usize) {
                let size_px = [TILE_PX.min(width - x), TILE_PX.min(height - y)];
                let tile = self.tile(&primitives, pixels_per_point, [x, y], size_px)?;
                image::imageops::replace(&mut picture, &tile, i64::from(x), i64::from(y));
            }
        }
        Ok(picture)
    }
}

#[cfg(test)]
mod tests {
    use egui_kittest::Harness;
    use zieglerlab::app::{Settings, ZieglerApp};

    use super::*;

    /// The default launch drawn with `renderer` at `size` points and `scale`
    /// pixels per point.
    fn picture(
        builder: egui_kittest::HarnessBuilder<ZieglerApp>,
        size: [f32; 2],
        scale: f32,
    ) -> RgbaImage {
        let app = ZieglerApp::new(Settings::default()).unwrap();
        let mut harness: Harness<'_, ZieglerApp> = builder
            .with_size(size)
            .with_pixels_per_point(scale)
            .build_ui_state(|ui, app: &mut ZieglerApp| app.contents_ui(ui), app);
        harness.run_steps(4);
        harness.render().unwrap()
    }

    /// Tiles put together are the picture drawn whole: no channel of any
    /// pixel differs by more than 2 levels of 255 (a few hundred of a
    /// million pixels differ by 1 or 2, blending rounded in another order),
    /// also at 3 pixels per point, where a tile's offset is not a whole
    /// number of points.
    #[test]
    fn tiles_make_the_whole_picture() {
        for (size, scale) in [([1280.0, 800.0], 1.0), ([720.0, 400.0], 3.0)] {
            let whole = picture(Harness::builder().wgpu(), size, scale);
            let tiled = picture(
                Harness::builder().renderer(TiledRenderer::new()),
                size,
                scale,
            );
            assert!(tiled.width() > TILE_PX && tiled.height() > TILE_PX || scale == 1.0);
            assert_eq!(whole.dimensions(), tiled.dimensions());
            let differing = whole
                .pixels()
                .zip(tiled.pixels())
                .filter(|(a, b)| a.0.iter().zip(b.0).any(|(x, y)| x.abs_diff(y) > 2))
                .count();
            assert_eq!(differing, 0, "pixels differ at {size:?} x {scale}");
        }
    }
}
