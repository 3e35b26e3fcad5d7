//! scratch
fn main() {
    use refraction_diagram::*;
    let s = ExplorerState::default();
    let doc = refraction_render::interface_svg(&s, &Overlay::default(), 1280, 720).unwrap();
    std::fs::write("/tmp/i.svg", doc).unwrap();
    refraction_render::render(&s, &Overlay::default(), 1280, 720)
        .unwrap()
        .save_png("/tmp/i.png")
        .unwrap();
}
