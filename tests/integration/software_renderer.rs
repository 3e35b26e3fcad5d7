//! The image snapshots' renderer: egui's triangles drawn on the CPU, the way egui's own wgpu
//! renderer draws them for kittest with its predictable filtering (egui-wgpu's `egui.wgsl`,
//! `fs_main_gamma_framebuffer` and `sample_texture`): colours in gamma space with premultiplied
//! alpha, texture times vertex colour, bilinear taps at texel centres, blending "one,
//! one minus source alpha", and the clip rectangle as a scissor rounded to whole pixels.
//!
//! It stands in for the GPU stack (wgpu, its shader compiler and Vulkan bindings, and Mesa's
//! software Vulkan driver on the CI machine), which took a fifth of a cold build for twenty
//! pictures.

use std::collections::HashMap;

use egui::epaint::textures::{TextureFilter, TextureWrapMode};
use egui::epaint::{ClippedPrimitive, ImageData, ImageDelta, Mesh, Primitive, Vertex};
use egui::{Color32, Pos2, Rect, TextureId, TexturesDelta};
use egui_kittest::TestRenderer;
use image::RgbaImage;

/// A colour with premultiplied alpha, each channel 0 to 1, in gamma space.
type Rgba = [f32; 4];

/// One texture as egui sent it.
struct Texture {
    width: usize,
    height: usize,
    pixels: Vec<Color32>,
    nearest: bool,
    wrap: TextureWrapMode,
}

impl Texture {
    /// The texel at `(x, y)`, wrapped into the texture as its wrap mode says.
    fn texel(&self, x: i64, y: i64) -> Rgba {
        let x = wrap(x, self.width, self.wrap);
        let y = wrap(y, self.height, self.wrap);
        unit(self.pixels[y * self.width + x])
    }

    /// The texture at `uv`: the nearest texel, or the four around it mixed bilinearly.
    fn sample(&self, uv: Pos2) -> Rgba {
        let (u, v) = (uv.x * self.width as f32, uv.y * self.height as f32);
        if self.nearest {
            return self.texel(u.floor() as i64, v.floor() as i64);
        }
        let (u, v) = (u - 0.5, v - 0.5);
        let (x, y) = (u.floor(), v.floor());
        let (fx, fy) = (u - x, v - y);
        let (x, y) = (x as i64, y as i64);
        let top = mix(self.texel(x, y), self.texel(x + 1, y), fx);
        let bottom = mix(self.texel(x, y + 1), self.texel(x + 1, y + 1), fx);
        mix(top, bottom, fy)
    }
}

/// `coord` brought into `0..size` by the wrap mode.
fn wrap(coord: i64, size: usize, mode: TextureWrapMode) -> usize {
    let size = size as i64;
    let inside = match mode {
        TextureWrapMode::ClampToEdge => coord.clamp(0, size - 1),
        TextureWrapMode::Repeat => coord.rem_euclid(size),
        TextureWrapMode::MirroredRepeat => {
            let folded = coord.rem_euclid(2 * size);
            if folded < size {
                folded
            } else {
                2 * size - 1 - folded
            }
        }
    };
    inside as usize
}

// The per-pixel helpers below spell out their four channels: the test binary is built
// without optimisation, where an array's `map` costs a call per channel.

/// `colour` with its channels from 0 to 1.
fn unit(colour: Color32) -> Rgba {
    let [r, g, b, a] = colour.to_array();
    [
        f32::from(r) / 255.0,
        f32::from(g) / 255.0,
        f32::from(b) / 255.0,
        f32::from(a) / 255.0,
    ]
}

fn mix(a: Rgba, b: Rgba, t: f32) -> Rgba {
    [
        a[0] + (b[0] - a[0]) * t,
        a[1] + (b[1] - a[1]) * t,
        a[2] + (b[2] - a[2]) * t,
        a[3] + (b[3] - a[3]) * t,
    ]
}

/// `a` times `b`, channel by channel.
fn times(a: Rgba, b: Rgba) -> Rgba {
    [a[0] * b[0], a[1] * b[1], a[2] * b[2], a[3] * b[3]]
}

/// The CPU renderer the snapshots are taken with (`HarnessBuilder::renderer`).
#[derive(Default)]
pub(crate) struct SoftwareRenderer {
    textures: HashMap<TextureId, Texture>,
}

impl SoftwareRenderer {
    /// Applies one image delta: a whole texture, or a patch of one already sent.
    fn set(&mut self, id: TextureId, delta: &ImageDelta) {
        let ImageData::Color(image) = &delta.image;
        let [width, height] = image.size;
        let nearest = delta.options.magnification == TextureFilter::Nearest;
        let wrap = delta.options.wrap_mode;
        match delta.pos {
            None => {
                let pixels = image.pixels.clone();
                let texture = Texture {
                    width,
                    height,
                    pixels,
                    nearest,
                    wrap,
                };
                self.textures.insert(id, texture);
            }
            Some([x0, y0]) => {
                let texture = self
                    .textures
                    .get_mut(&id)
                    .expect("a patch comes after its texture");
                for (row, pixels) in image.pixels.chunks(width).enumerate() {
                    let start = (y0 + row) * texture.width + x0;
                    texture.pixels[start..start + width].copy_from_slice(pixels);
                }
            }
        }
    }
}

impl TestRenderer for SoftwareRenderer {
    fn handle_delta(&mut self, delta: &mut TexturesDelta) {
        // Each texture's deltas are applied in their order; textures are independent.
        #[expect(
            clippy::iter_over_hash_type,
            reason = "the textures do not touch each other"
        )]
        for (id, deltas) in delta.set.drain() {
            for image_delta in &deltas {
                self.set(id, image_delta);
            }
        }
        #[expect(clippy::iter_over_hash_type, reason = "freeing has no order")]
        for id in delta.free.drain() {
            self.textures.remove(&id);
        }
    }

    fn render(
        &mut self,
        ctx: &egui::Context,
        output: &egui::FullOutput,
    ) -> Result<RgbaImage, String> {
        let pixels_per_point = ctx.pixels_per_point();
        let size = ctx.content_rect().size() * pixels_per_point;
        let mut canvas = Canvas::new(size.x.round() as usize, size.y.round() as usize);
        for ClippedPrimitive {
            clip_rect,
            primitive,
        } in ctx.tessellate(output.shapes.clone(), pixels_per_point)
        {
            let Primitive::Mesh(mesh) = primitive else {
                return Err("a paint callback cannot be drawn without a GPU".to_owned());
            };
            let texture = self
                .textures
                .get(&mesh.texture_id)
                .ok_or_else(|| format!("texture {:?} was never sent", mesh.texture_id))?;
            let scissor = canvas.scissor(clip_rect, pixels_per_point);
            canvas.draw(&mesh, texture, scissor, pixels_per_point);
        }
        Ok(canvas.image())
    }
}

/// The picture being drawn, premultiplied, row by row.
struct Canvas {
    width: usize,
    height: usize,
    pixels: Vec<Rgba>,
}

/// Pixel bounds, the end exclusive.
#[derive(Clone, Copy)]
struct Bounds {
    x0: usize,
    y0: usize,
    x1: usize,
    y1: usize,
}

impl Canvas {
    /// A transparent canvas of `width` × `height` pixels, as the GPU's target is cleared.
    fn new(width: usize, height: usize) -> Self {
        let pixels = vec![[0.0; 4]; width * height];
        Self {
            width,
            height,
            pixels,
        }
    }

    /// The clip rectangle in pixels, rounded and kept inside the canvas as egui-wgpu does.
    fn scissor(&self, clip: Rect, pixels_per_point: f32) -> Bounds {
        let round =
            |v: f32, max: usize| ((v * pixels_per_point).round().max(0.0) as usize).min(max);
        let (x0, y0) = (
            round(clip.min.x, self.width),
            round(clip.min.y, self.height),
        );
        let x1 = round(clip.max.x, self.width).max(x0);
        let y1 = round(clip.max.y, self.height).max(y0);
        Bounds { x0, y0, x1, y1 }
    }

    fn draw(&mut self, mesh: &Mesh, texture: &Texture, scissor: Bounds, pixels_per_point: f32) {
        for triangle in mesh.indices.chunks_exact(3) {
            let [a, b, c] = [0, 1, 2].map(|i| {
                let vertex = mesh.vertices[triangle[i] as usize];
                Vertex {
                    pos: (vertex.pos.to_vec2() * pixels_per_point).to_pos2(),
                    ..vertex
                }
            });
            self.triangle([a, b, c], texture, scissor);
        }
    }

    /// Fills the pixels whose centres lie in the triangle, row by row over the span the
    /// triangle covers. A pixel centre on an edge shared by two triangles belongs to exactly
    /// one of them, so a translucent fill has no seam.
    fn triangle(&mut self, [a, mut b, mut c]: [Vertex; 3], texture: &Texture, scissor: Bounds) {
        let mut area = edge(a.pos, b.pos, c.pos);
        if area == 0.0 {
            return;
        }
        if area < 0.0 {
            core::mem::swap(&mut b, &mut c);
            area = -area;
        }
        let fill = Fill::new([a, b, c], texture);
        let edges = [(b.pos, c.pos), (c.pos, a.pos), (a.pos, b.pos)];
        let owned = edges.map(|(from, to)| owns_edge(from, to));
        let (top, bottom) = (
            a.pos.y.min(b.pos.y).min(c.pos.y),
            a.pos.y.max(b.pos.y).max(c.pos.y),
        );
        let y0 = (top.floor().max(0.0) as usize).max(scissor.y0);
        let y1 = (bottom.ceil().max(0.0) as usize).min(scissor.y1);
        for y in y0..y1 {
            let centre_y = y as f32 + 0.5;
            let Some((left, right)) = span(&edges, centre_y) else {
                continue;
            };
            // A pixel either side of the span is tested too: the span is only a bound.
            let x0 = ((left - 1.5).floor().max(0.0) as usize).max(scissor.x0);
            let x1 = ((right + 1.5).ceil().max(0.0) as usize).min(scissor.x1);
            for x in x0..x1 {
                let p = Pos2::new(x as f32 + 0.5, centre_y);
                let (wa, wb, wc) = (
                    edge(edges[0].0, edges[0].1, p),
                    edge(edges[1].0, edges[1].1, p),
                    edge(edges[2].0, edges[2].1, p),
                );
                if inside(wa, owned[0]) && inside(wb, owned[1]) && inside(wc, owned[2]) {
                    let source = fill.at([wa / area, wb / area, wc / area], texture);
                    let target = &mut self.pixels[y * self.width + x];
                    let keep = 1.0 - source[3];
                    *target = [
                        source[0] + target[0] * keep,
                        source[1] + target[1] * keep,
                        source[2] + target[2] * keep,
                        source[3] + target[3] * keep,
                    ];
                }
            }
        }
    }

    /// The picture as 8-bit RGBA, premultiplied as the GPU's target holds it.
    fn image(&self) -> RgbaImage {
        let byte = |c: f32| (c.clamp(0.0, 1.0) * 255.0).round() as u8;
        let mut bytes = Vec::with_capacity(self.pixels.len() * 4);
        for &[r, g, b, a] in &self.pixels {
            bytes.extend_from_slice(&[byte(r), byte(g), byte(b), byte(a)]);
        }
        RgbaImage::from_raw(self.width as u32, self.height as u32, bytes)
            .expect("the buffer has the picture's size")
    }
}

/// What a triangle paints: its vertices' colours and texture coordinates, or the one colour it
/// paints everywhere when its vertices agree (most of egui's shapes: a flat colour on the
/// font texture's white texel).
struct Fill {
    colours: [Rgba; 3],
    uvs: [Pos2; 3],
    flat: Option<Rgba>,
}

impl Fill {
    fn new(vertices: [Vertex; 3], texture: &Texture) -> Self {
        let colours = vertices.map(|v| unit(v.color));
        let uvs = vertices.map(|v| v.uv);
        let same = |x: [Pos2; 3]| x[0] == x[1] && x[1] == x[2];
        let flat = (colours[0] == colours[1] && colours[1] == colours[2] && same(uvs))
            .then(|| times(colours[0], texture.sample(uvs[0])));
        Self { colours, uvs, flat }
    }

    /// The premultiplied colour at the point with these barycentric `weights`.
    fn at(&self, [wa, wb, wc]: [f32; 3], texture: &Texture) -> Rgba {
        if let Some(flat) = self.flat {
            return flat;
        }
        let [ua, ub, uc] = self.uvs;
        let uv = Pos2::new(
            wa * ua.x + wb * ub.x + wc * uc.x,
            wa * ua.y + wb * ub.y + wc * uc.y,
        );
        let [ca, cb, cc] = self.colours;
        let colour = [
            wa * ca[0] + wb * cb[0] + wc * cc[0],
            wa * ca[1] + wb * cb[1] + wc * cc[1],
            wa * ca[2] + wb * cb[2] + wc * cc[2],
            wa * ca[3] + wb * cb[3] + wc * cc[3],
        ];
        times(colour, texture.sample(uv))
    }
}

/// The horizontal extent, in x, of the row `y` inside the triangle with these edges, or
/// `None` when the row misses it. Each edge keeps its inner side (edge > 0): a bound on x.
fn span(edges: &[(Pos2, Pos2); 3], y: f32) -> Option<(f32, f32)> {
    let (mut left, mut right) = (f32::NEG_INFINITY, f32::INFINITY);
    for &(from, to) in edges {
        let (dx, dy) = (to.x - from.x, to.y - from.y);
        // edge = dx·(y − from.y) − dy·(x − from.x) > 0
        let at_origin = dx * (y - from.y) + dy * from.x;
        if dy > 0.0 {
            right = right.min(at_origin / dy);
        } else if dy < 0.0 {
            left = left.max(at_origin / dy);
        } else if at_origin < 0.0 {
            // A horizontal edge with the row on its outer side.
            return None;
        }
    }
    (left <= right + 2.0).then_some((left, right))
}

/// Twice the signed area of `from`, `to`, `p`: positive when `p` is on the inner side of a
/// triangle wound as the rasterizer winds it.
fn edge(from: Pos2, to: Pos2, p: Pos2) -> f32 {
    (to.x - from.x) * (p.y - from.y) - (to.y - from.y) * (p.x - from.x)
}

/// Whether a pixel centre with edge value `w` is inside that edge (`owned`: the edge's own
/// centres count, see [`owns_edge`]).
fn inside(w: f32, owned: bool) -> bool {
    w > 0.0 || (w == 0.0 && owned)
}

/// Whether a pixel centre exactly on the edge `from`→`to` belongs to this triangle: of the two
/// triangles sharing an edge, which run along it in opposite directions, exactly one does.
fn owns_edge(from: Pos2, to: Pos2) -> bool {
    let (dx, dy) = (to.x - from.x, to.y - from.y);
    dy < 0.0 || (dy == 0.0 && dx > 0.0)
}

/// A translucent square of two triangles, its diagonal through pixel centres: every pixel in
/// it is painted once, none outside.
#[test]
fn a_translucent_square_has_no_seam_and_stays_inside_its_edges() {
    let white = Texture {
        width: 1,
        height: 1,
        pixels: vec![Color32::WHITE],
        nearest: false,
        wrap: TextureWrapMode::ClampToEdge,
    };
    let mut mesh = Mesh::default();
    let rect = Rect::from_min_max(Pos2::new(2.0, 2.0), Pos2::new(12.0, 12.0));
    mesh.add_colored_rect(rect, Color32::from_black_alpha(128));
    let mut canvas = Canvas::new(16, 16);
    let all = Bounds {
        x0: 0,
        y0: 0,
        x1: 16,
        y1: 16,
    };
    canvas.draw(&mesh, &white, all, 1.0);
    let image = canvas.image();
    for (x, y, pixel) in image.enumerate_pixels() {
        let expected = if (2..12).contains(&x) && (2..12).contains(&y) {
            128
        } else {
            0
        };
        assert_eq!(pixel.0[3], expected, "alpha at ({x}, {y})");
    }
}
