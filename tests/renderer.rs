//! The common path (`render::Renderer`): the reference torus through it equals its golden
//! image in one pass and in bands of any height, with bins and without; a prepared frame drawn
//! from two threads gives the image of one pass; wire and solid models occlude each other;
//! each setup error is reported, never a panic; a band draws a model in mesh order.

mod common;

use common::golden;
use common::scene::*;
use embedded_graphics::pixelcolor::{Rgb565, Rgb888, RgbColor};
use fixed3d::buffer::Carried;
use fixed3d::camera::{Camera, CameraError};
use fixed3d::mesh::{Mesh, CUBE};
use fixed3d::pipeline::{Bin, Cull, ScreenVertex, Stats};
use fixed3d::projection::{ProjectionError, Viewport};
use fixed3d::render::{Model, PreparedFrame, RenderError, Renderer, Shade, Storage, MAX_LIGHTS};
use fixed3d::scene::{Light, LightError};

/// The renderer's display: Rgb565, blank where nothing was written.
type Screen = common::screen::Screen<Rgb565>;

/// A `w` x `h` display.
fn screen(w: u32, h: u32) -> Screen {
    Screen::new(w, h, Rgb565::new(1, 2, 3))
}

fn camera() -> Camera {
    Camera::perspective(60, 1, 10).looking_at([0.0, 0.0, 2.6], [0, 0, 0])
}

fn lights() -> [Light; 2] {
    [Light::ambient(0.2), Light::directional([-1, 1, 1], 0.8)]
}

/// Renders `models` through buffers of `rows` rows and storage for `bins` bins (and room to
/// carry 32 triangles from band to band, as `Storage` has by default).
fn render(models: &[Model<'_>], rows: u32, bins: usize) -> (Screen, Stats) {
    render_with(models, &camera(), rows, (bins, 32))
}

/// Renders `models` seen by `camera` through buffers of `rows` rows, with storage for `bins`
/// bins and room to carry `carried` triangles.
fn render_with(
    models: &[Model<'_>],
    camera: &Camera,
    rows: u32,
    (bins, carried): (usize, usize),
) -> (Screen, Stats) {
    let mut screen = screen(320, 240);
    let vertices: usize = models.iter().map(|m| m.mesh().positions().len()).sum();
    let (mut v, mut b) = (
        vec![ScreenVertex::DEFAULT; vertices],
        vec![Bin::EMPTY; bins],
    );
    let mut room = vec![Carried::EMPTY; carried];
    let (mut c, mut d) = (
        vec![Rgb565::BLACK; (320 * rows) as usize],
        vec![0u16; (320 * rows) as usize],
    );
    let stats = Renderer::from_slices(&mut v, &mut b, &mut c, &mut d)
        .with_carried(&mut room)
        .render(models, &lights(), camera, &mut screen)
        .unwrap();
    (screen, stats)
}

/// The reference torus through the renderer is the golden image of the lower layers, drawn in
/// one pass, in bands of every kind of height (one row, a prime, a divisor of 240, the
/// `bands` preset's 12, most of the frame), with bins for every triangle, for the visible
/// ones only, and with too few (every band then walks every triangle).
#[test]
fn torus_through_the_renderer_equals_its_golden_image() {
    let data = torus_f64();
    let mesh = Mesh::new(&data.positions, &data.triangles).unwrap();
    let torus = [Model::new(&mesh, BASE)];
    let (one_pass, stats) = render(&torus, 240, 0);
    golden::check("torus_flat", 320, 240, &one_pass.rgb());
    assert_eq!(
        one_pass.writes,
        320 * 240,
        "one fill_contiguous of the whole frame"
    );
    assert!(stats.drawn > 900 && stats.culled > 1100, "{stats:?}");
    for rows in [1, 7, 12, 16, 100, 239] {
        for bins in [2304, 1000, 10] {
            let (banded, band_stats) = render(&torus, rows, bins);
            assert!(
                banded.pixels == one_pass.pixels,
                "bands of {rows} rows with {bins} bins differ from one pass"
            );
            assert_eq!(banded.writes, 320 * 240);
            if bins >= 1000 {
                // Binned: each triangle culled once, not once a band.
                assert_eq!(
                    (band_stats.culled, band_stats.primitives),
                    (stats.culled, 2304)
                );
            }
        }
    }
}

/// Solid triangles that cross a band's last row are carried into the next band: the frame is
/// the one pass's with room to carry every one, a few, one, or none, in bands of several
/// heights, for a flat torus and an unlit cube together, seen from afar and from so near that
/// the near plane and the guard band cut the scene (the pieces of a clipped triangle are set
/// up again in each band). Every band draws the triangles it carried, none twice.
#[test]
fn carried_triangles_draw_the_frame_of_one_pass() {
    let data = torus_f64();
    let mesh = Mesh::new(&data.positions, &data.triangles).unwrap();
    let models = [
        Model::new(&mesh, BASE).rotated_x(25).rotated_y(10),
        Model::new(&CUBE, Rgb888::CYAN)
            .shaded(Shade::Unlit)
            .scaled(0.3)
            .translated([0.4, 0.1, 0.5]),
    ];
    let near = Camera::perspective(60, 1, 10).looking_at([0.3, 0.2, 1.1], [0, 0, 0]);
    for camera in [camera(), near] {
        let (one_pass, full) = render_with(&models, &camera, 240, (4000, 64));
        assert_eq!(full.carried, 0, "one pass carries nothing");
        for rows in [1, 12, 13, 60] {
            let mut carried = Vec::new();
            for room in [200, 64, 3, 1, 0] {
                let (banded, stats) = render_with(&models, &camera, rows, (4000, room));
                assert!(
                    banded.pixels == one_pass.pixels,
                    "bands of {rows} rows, room for {room}"
                );
                assert_eq!(banded.writes, 320 * 240);
                assert!(stats.carried <= stats.drawn);
                carried.push(stats.carried);
            }
            // More room carries more, at most as many across each band boundary as it holds;
            // none carries nothing.
            let boundaries = 240 / rows;
            assert!(carried.windows(2).all(|w| w[0] >= w[1]), "{carried:?}");
            assert!(carried[0] > carried[2] && carried[4] == 0, "{carried:?}");
            assert!(carried[2] <= 3 * boundaries && carried[3] <= boundaries);
        }
    }
    // Without bins every band walks every triangle: nothing is carried (no bin to match).
    let (one_pass, _) = render_with(&models, &camera(), 240, (0, 64));
    let (banded, stats) = render_with(&models, &camera(), 12, (0, 64));
    assert!(banded.pixels == one_pass.pixels);
    assert_eq!(stats.carried, 0);
}

/// A renderer over `Storage` carries into its room: the torus drawn in bands through it
/// carries triangles and gives the frame drawn without room.
#[test]
fn a_renderer_over_storage_carries_triangles() {
    let data = torus_f64();
    let mesh = Mesh::new(&data.positions, &data.triangles).unwrap();
    let torus = [Model::new(&mesh, BASE)];
    let (without, _) = render_with(&torus, &camera(), 12, (2304, 0));
    let mut storage = Box::new(Storage::<1152, 2304>::new());
    let (mut c, mut d) = (vec![Rgb565::BLACK; 320 * 12], vec![0u16; 320 * 12]);
    let mut screen = screen(320, 240);
    let stats = Renderer::new(&mut storage, &mut c, &mut d)
        .render(&torus, &lights(), &camera(), &mut screen)
        .unwrap();
    assert!(stats.carried > 0, "{stats:?}");
    assert!(screen.pixels == without.pixels);
}

/// Two coplanar triangles, one in each of two unlit models, overlapping, in different
/// colours: where their depths tie the first model's shows, as in one pass, also where the
/// band before carried it (its top row is above the band in which the second begins).
#[test]
fn carried_triangles_keep_their_place_in_the_order() {
    use fixed3d::math::Vec3;
    let v = |x: f64, y: f64| Vec3::from([x, y, 0.0]);
    let first = [v(-0.8, 0.7), v(-0.2, -0.6), v(0.8, 0.5)];
    let second = [v(-0.6, 0.1), v(0.0, -0.7), v(0.7, 0.0)];
    let triangle = [[0u16, 1, 2]];
    let (a, b) = (
        Mesh::new(&first, &triangle).unwrap(),
        Mesh::new(&second, &triangle).unwrap(),
    );
    let unlit = |mesh, color| Model::new(mesh, color).shaded(Shade::Unlit);
    let models = [unlit(&a, Rgb888::RED), unlit(&b, Rgb888::GREEN)];
    let swapped = [unlit(&b, Rgb888::GREEN), unlit(&a, Rgb888::RED)];
    let (one_pass, _) = render(&models, 240, 2);
    let (other, _) = render(&swapped, 240, 2);
    assert!(one_pass.pixels != other.pixels, "no pixel ties");
    for rows in [4, 13, 16, 40] {
        let (banded, stats) = render(&models, rows, 2);
        assert!(banded.pixels == one_pass.pixels, "bands of {rows} rows");
        assert!(stats.carried > 0, "{stats:?}");
    }
}

/// A prepared frame drawn band by band from two threads at once (odd and even bands, each
/// thread with its own buffers, as two cores of an RP2040 would) gives the image of one pass.
#[test]
fn prepared_frame_drawn_from_two_threads_equals_one_pass() {
    let data = torus_f64();
    let mesh = Mesh::new(&data.positions, &data.triangles).unwrap();
    let models = [
        Model::new(&mesh, BASE).rotated_y(20),
        Model::new(&CUBE, Rgb888::CYAN)
            .scaled(0.3)
            .translated([0.5, 0.2, 0.5]),
    ];
    let (one_pass, _) = render(&models, 240, 4000);
    let vertices = mesh.positions().len() + CUBE.positions().len();
    let (mut v, mut b) = (
        vec![ScreenVertex::DEFAULT; vertices],
        vec![Bin::EMPTY; 4000],
    );
    let viewport = Viewport::new(320, 240).unwrap();
    let lights = lights();
    let camera = camera();
    let frame = PreparedFrame::new(
        &models,
        &lights,
        &camera,
        viewport,
        Cull::Back,
        &mut v,
        &mut b,
    )
    .unwrap();
    const ROWS: u32 = 10;
    let bands = |parity: u32| {
        let frame = &frame;
        move || {
            let mut out = Vec::new();
            let (mut c, mut d) = (
                vec![Rgb565::BLACK; 320 * ROWS as usize],
                vec![0u16; 320 * ROWS as usize],
            );
            for band in (parity..240 / ROWS).step_by(2) {
                c.fill(Rgb565::BLACK);
                d.fill(u16::MAX);
                frame.draw_band(band * ROWS, &mut c, &mut d).unwrap();
                out.push((band, c.clone()));
            }
            out
        }
    };
    let (even, odd) = std::thread::scope(|s| {
        let even = s.spawn(bands(0));
        let odd = s.spawn(bands(1));
        (even.join().unwrap(), odd.join().unwrap())
    });
    let mut image = vec![Rgb565::BLACK; 320 * 240];
    for (band, pixels) in even.into_iter().chain(odd) {
        let start = (band * ROWS * 320) as usize;
        image[start..start + pixels.len()].copy_from_slice(&pixels);
    }
    assert!(image == one_pass.pixels);
}

/// Many models stacked down the screen, each band meeting a few of them: every band sets up
/// only the models it meets, each with its own vertices, and the image equals one pass (in
/// bands of one row, of a prime and of the `bands` preset's 12), every model seen.
#[test]
fn bands_of_many_models_equal_one_pass() {
    let models: Vec<Model<'_>> = (0..12)
        .map(|i| {
            let (column, row) = (f64::from(i % 3), f64::from(i / 3));
            Model::new(
                &CUBE,
                Rgb888::new(60 + 15 * i as u8, 200, 255 - 10 * i as u8),
            )
            .scaled(0.35)
            .rotated_y(25 * i)
            .rotated_x(10 * i)
            .translated([0.9 * column - 0.9, 1.05 - 0.7 * row, 0.0])
        })
        .collect();
    let (one_pass, stats) = render(&models, 240, 0);
    assert!(stats.drawn >= 12 * 3, "{stats:?}");
    for rows in [1, 7, 12] {
        let (banded, _) = render(&models, rows, 12 * 12);
        assert!(banded.pixels == one_pass.pixels, "{rows}-row bands");
    }
    // Every model shows: without it the image differs.
    for i in 0..models.len() {
        let mut others = models.clone();
        others.remove(i);
        assert!(
            render(&others, 240, 0).0.pixels != one_pass.pixels,
            "model {i}"
        );
    }
}

/// A band that draws nothing leaves its buffers as it found them, so the renderer clears them
/// only after a band that drew: one renderer draws a small cube at the top of the screen, at
/// the bottom (its last band drew into the buffers the next frame starts with), then in the
/// middle, on a background colour, each frame the one pass's, and most bands empty.
#[test]
fn bands_after_empty_ones_equal_one_pass() {
    let background = Rgb565::new(3, 9, 27);
    let cube = |y: f64| {
        [Model::new(&CUBE, Rgb888::new(250, 180, 40))
            .scaled(0.2)
            .rotated_y(30)
            .rotated_x(20)
            .translated([0.3, y, 0.0])]
    };
    let (mut v, mut b) = (vec![ScreenVertex::DEFAULT; 8], vec![Bin::EMPTY; 12]);
    let mut room = vec![Carried::EMPTY; 8];
    let (mut c, mut d) = (vec![Rgb565::BLACK; 320 * 10], vec![0u16; 320 * 10]);
    let mut renderer = Renderer::from_slices(&mut v, &mut b, &mut c, &mut d)
        .with_carried(&mut room)
        .with_background(background);
    for y in [1.2, -1.2, 0.0] {
        let models = cube(y);
        let mut banded = screen(320, 240);
        let stats = renderer.render(&models, &lights(), &camera(), &mut banded);
        assert!(stats.unwrap().drawn > 0);
        let mut one_pass = screen(320, 240);
        let (mut v1, mut c1, mut d1) = (
            vec![ScreenVertex::DEFAULT; 8],
            vec![Rgb565::BLACK; 320 * 240],
            vec![0u16; 320 * 240],
        );
        Renderer::from_slices(&mut v1, &mut [], &mut c1, &mut d1)
            .with_background(background)
            .render(&models, &lights(), &camera(), &mut one_pass)
            .unwrap();
        assert!(banded.pixels == one_pass.pixels, "cube at {y}");
        // The cube covers a few bands' rows; the others show the background alone.
        let empty = banded
            .pixels
            .chunks(320 * 10)
            .filter(|band| band.iter().all(|&p| p == background))
            .count();
        assert!(empty >= 16, "cube at {y}: {empty} empty bands");
    }
}

/// A wireframe model and a solid one in one scene: the cube's edges behind the torus are
/// hidden by it, those in front are drawn over it (golden image), and the image is the same
/// in bands.
#[test]
#[cfg(feature = "wireframe")]
fn wire_and_solid_models_occlude_each_other() {
    let data = torus_f64();
    let mesh = Mesh::new(&data.positions, &data.triangles).unwrap();
    let models = [
        Model::new(&mesh, BASE),
        Model::new(&CUBE, Rgb888::WHITE)
            .scaled(0.9)
            .rotated_y(30)
            .wireframe(),
    ];
    let (one_pass, _) = render(&models, 240, 2304);
    golden::check("renderer_wire_and_solid", 320, 240, &one_pass.rgb());
    let (banded, _) = render(&models, 16, 2304);
    assert!(banded.pixels == one_pass.pixels);
    // Both kinds of occlusion happen: some wire pixels hidden, some drawn over the torus.
    let (torus_only, _) = render(&models[..1], 240, 2304);
    let (wire_only, _) = render(&models[1..], 240, 0);
    let white = Rgb565::WHITE;
    let (mut hidden, mut over) = (0, 0);
    for i in 0..320 * 240 {
        let torus_there = torus_only.pixels[i] != Rgb565::BLACK;
        if wire_only.pixels[i] == white && torus_there {
            if one_pass.pixels[i] == white {
                over += 1;
            } else {
                hidden += 1;
            }
        }
    }
    assert!(hidden > 50 && over > 50, "hidden {hidden}, over {over}");
}

/// Every shading through the renderer, Gouraud on a mesh with vertex normals: each draws, and
/// bands equal one pass.
#[test]
#[cfg(feature = "gouraud")]
fn every_shade_draws_the_same_in_bands() {
    let data = torus_f64();
    let mesh = Mesh::new(&data.positions, &data.triangles)
        .unwrap()
        .with_normals(&data.normals)
        .unwrap();
    for shade in [
        Shade::Unlit,
        Shade::Flat,
        Shade::Gouraud,
        Shade::PerspectiveGouraud,
    ] {
        let models = [Model::new(&mesh, BASE).rotated_x(15).shaded(shade)];
        let (one_pass, stats) = render(&models, 240, 2304);
        assert!(stats.drawn > 900, "{shade:?}");
        let (banded, _) = render(&models, 13, 2304);
        assert!(banded.pixels == one_pass.pixels, "{shade:?}");
    }
}

/// Setup errors are errors: too many lights, a zero light direction, a camera at its target,
/// a bad lens, too little storage, buffers shorter than a row, an empty display.
#[test]
fn setup_errors_are_reported() {
    let models = [Model::new(&CUBE, Rgb888::RED)];
    let try_render = |lights: &[Light], camera: &Camera, vertices: usize, cells: usize, w: u32| {
        let mut screen = screen(w, 8);
        let (mut v, mut b) = (vec![ScreenVertex::DEFAULT; vertices], vec![Bin::EMPTY; 12]);
        let (mut c, mut d) = (vec![Rgb565::BLACK; cells], vec![0u16; cells]);
        Renderer::from_slices(&mut v, &mut b, &mut c, &mut d)
            .render(&models, lights, camera, &mut screen)
            .map(|_| ())
    };
    let ok_camera = camera();
    assert_eq!(try_render(&lights(), &ok_camera, 8, 64, 8), Ok(()));
    let many = [Light::directional([0, 0, 1], 0.1); MAX_LIGHTS + 1];
    assert_eq!(
        try_render(&many, &ok_camera, 8, 64, 8),
        Err(RenderError::Lights(LightError::Full))
    );
    let zero = [Light::directional([0, 0, 0], 1)];
    assert_eq!(
        try_render(&zero, &ok_camera, 8, 64, 8),
        Err(RenderError::Lights(LightError::ZeroDirection))
    );
    let at_target = Camera::perspective(60, 1, 10).looking_at([1, 1, 1], [1, 1, 1]);
    assert_eq!(
        try_render(&lights(), &at_target, 8, 64, 8),
        Err(RenderError::Camera(CameraError::EyeAtTarget))
    );
    let inverted = Camera::perspective(60, 10, 1).looking_at([0, 0, 3], [0, 0, 0]);
    assert_eq!(
        try_render(&lights(), &inverted, 8, 64, 8),
        Err(RenderError::Projection(ProjectionError::FarNotBeyondNear))
    );
    assert_eq!(
        try_render(&lights(), &ok_camera, 7, 64, 8),
        Err(RenderError::CacheTooSmall {
            needed: 8,
            capacity: 7
        })
    );
    assert_eq!(
        try_render(&lights(), &ok_camera, 8, 7, 8),
        Err(RenderError::BuffersTooSmall { row: 8 })
    );
    assert_eq!(
        try_render(&lights(), &ok_camera, 8, 64, 0),
        Err(RenderError::Viewport(ProjectionError::ViewportSize))
    );
}

/// The common path stays short: examples/hello_cube.rs, a whole program, has a `main` of at
/// most 25 lines and imports at most 6 names from fixed3d.
#[test]
fn hello_cube_is_short() {
    let source = include_str!("../examples/hello_cube.rs");
    let lines: Vec<&str> = source.lines().collect();
    let start = lines.iter().position(|l| l.starts_with("fn main")).unwrap();
    let end = start + lines[start..].iter().position(|l| *l == "}").unwrap();
    assert!(end - start - 1 <= 25, "main has {} lines", end - start - 1);
    let names: usize = lines
        .iter()
        .filter_map(|l| l.strip_prefix("use fixed3d::"))
        .map(|l| match l.find('{') {
            Some(i) => l[i..].split(',').count(),
            None => 1,
        })
        .sum();
    assert!(names <= 6, "{names} names imported from fixed3d");
}

/// An unlit model through the renderer (flat shading under a white ambient light alone) is the
/// lower layers' `Unlit` image, pixel for pixel.
#[test]
fn unlit_models_keep_their_colour() {
    use fixed3d::buffer::{ColorDepth, DepthBuffer, FrameBuffer};
    use fixed3d::mesh::Object;
    use fixed3d::scene::{LightColor, Lighting, Scene};
    use fixed3d::shade::Unlit;
    let data = torus_f64();
    let mesh = Mesh::new(&data.positions, &data.triangles).unwrap();
    let (through_renderer, _) = render(&[Model::new(&mesh, BASE).shaded(Shade::Unlit)], 20, 2304);
    let objects = [Object::new(&mesh, fixed3d::math::Mat4::IDENTITY, BASE)];
    let scene = Scene::new(&objects, Lighting::<0>::new(LightColor::BLACK));
    let mut cache = vec![ScreenVertex::DEFAULT; mesh.positions().len()];
    let prepared = frame().prepare(&scene, &mut cache, Unlit).unwrap();
    let (mut c, mut d) = (vec![Rgb565::BLACK; 320 * 240], vec![u16::MAX; 320 * 240]);
    let mut color = FrameBuffer::new(&mut c, 320, 240).unwrap();
    let mut depth = DepthBuffer::new(&mut d, 320, 240).unwrap();
    prepared
        .draw(&mut ColorDepth::new(&mut color, &mut depth).unwrap())
        .unwrap();
    assert!(through_renderer.pixels == c);
    assert!(c.iter().filter(|&&p| p == Rgb565::from(BASE)).count() > 28_000);
}

/// Without the `gouraud`, `point-light`, `specular`, `texture` and `wireframe` features a model
/// or light that needs one is an error naming it (and the build links none of their code).
#[test]
#[cfg(not(all(
    feature = "gouraud",
    feature = "point-light",
    feature = "specular",
    feature = "texture",
    feature = "wireframe"
)))]
fn models_needing_a_missing_feature_are_errors() {
    use fixed3d::texture::{Texels, Texture};
    let mut screen = screen(32, 32);
    let (mut v, mut b) = (vec![ScreenVertex::DEFAULT; 8], vec![Bin::EMPTY; 12]);
    let (mut c, mut d) = (vec![Rgb565::BLACK; 32 * 32], vec![0u16; 32 * 32]);
    let mut renderer = Renderer::from_slices(&mut v, &mut b, &mut c, &mut d);
    let cube = Model::new(&CUBE, Rgb888::RED);
    let texels = [Rgb888::RED];
    let texture = Texture::new(Texels::from(&texels), 1, 1).unwrap();
    static GLOSS: fixed3d::mesh::Specular = fixed3d::mesh::Specular::new(Rgb888::WHITE, 8);
    for (model, feature, on) in [
        (
            cube.shaded(Shade::Gouraud),
            "gouraud",
            cfg!(feature = "gouraud"),
        ),
        (cube.wireframe(), "wireframe", cfg!(feature = "wireframe")),
        (
            cube.shaded(Shade::Gouraud).glossy(&GLOSS),
            // A glossy Gouraud model needs both; without `gouraud` that one is named.
            if cfg!(feature = "gouraud") {
                "specular"
            } else {
                "gouraud"
            },
            cfg!(all(feature = "gouraud", feature = "specular")),
        ),
        (
            cube.textured(&texture),
            "texture",
            cfg!(feature = "texture"),
        ),
    ] {
        let drawn = renderer.render(&[model], &lights(), &camera(), &mut screen);
        if !on {
            assert_eq!(drawn, Err(RenderError::Disabled { feature }));
        }
    }
    let lamp = [Light::point([0, 2, 2], 1)];
    let drawn = renderer.render(&[cube], &lamp, &camera(), &mut screen);
    if !cfg!(feature = "point-light") {
        let feature = "point-light";
        assert_eq!(drawn, Err(RenderError::Disabled { feature }));
    }
}

/// The viewport is the display's bounding box wherever it lies: through an embedded-graphics
/// `translated` view (its box moved off the origin) the frame lands on the same pixels.
#[test]
fn a_display_whose_box_is_off_the_origin_gets_the_same_frame() {
    use embedded_graphics::draw_target::DrawTargetExt;
    use embedded_graphics::geometry::Point;
    let data = torus_f64();
    let mesh = Mesh::new(&data.positions, &data.triangles).unwrap();
    let models = [Model::new(&mesh, BASE)];
    let (direct, _) = render(&models, 16, 2304);
    let mut screen = screen(320, 240);
    let (mut v, mut b) = (vec![ScreenVertex::DEFAULT; 1152], vec![Bin::EMPTY; 2304]);
    let (mut c, mut d) = (vec![Rgb565::BLACK; 320 * 16], vec![0u16; 320 * 16]);
    let mut view = screen.translated(Point::new(7, -3));
    Renderer::from_slices(&mut v, &mut b, &mut c, &mut d)
        .render(&models, &lights(), &camera(), &mut view)
        .unwrap();
    assert!(screen.pixels == direct.pixels);
}

/// Two coplanar triangles of one model, overlapping, lit differently (Gouraud, each with its
/// own vertex normals): where their depths tie, the first in the mesh shows, as in one pass,
/// in bands whose first holds the second triangle's top row and not the first's. Their order
/// matters (swapped, one pass differs), so bands that drew by rows would differ.
#[test]
#[cfg(feature = "gouraud")]
fn bands_draw_a_model_in_mesh_order() {
    use fixed3d::math::Vec3;
    let v = |x: f64, y: f64| Vec3::from([x, y, 0.0]);
    let positions = [
        v(-0.8, -0.6),
        v(0.8, -0.6),
        v(0.0, 0.3),
        v(-0.6, -0.3),
        v(0.6, -0.3),
        v(0.0, 0.7),
    ];
    let (front, tilted) = (Vec3::from([0, 0, 1]), Vec3::from([0.8, 0.0, 0.6]));
    let normals = [front, front, front, tilted, tilted, tilted];
    let image = |triangles: &[[u16; 3]], rows: u32| {
        let mesh = Mesh::new(&positions, triangles)
            .unwrap()
            .with_normals(&normals)
            .unwrap();
        let models = [Model::new(&mesh, BASE).shaded(Shade::Gouraud)];
        let (screen, stats) = render(&models, rows, 2);
        assert!(stats.drawn >= 2, "{stats:?}");
        screen.pixels
    };
    let (first, second) = ([0, 1, 2], [3, 4, 5]);
    let one_pass = image(&[first, second], 240);
    assert!(one_pass != image(&[second, first], 240), "no pixel ties");
    for rows in [4, 13, 16, 40] {
        assert!(
            image(&[first, second], rows) == one_pass,
            "bands of {rows} rows"
        );
    }
}
