//! The render loop: pixels in parallel with `rayon`, progress with `indicatif`.

use crate::integrator::Integrator;
use crate::rng::pixel_rng;
use crate::scene::Scene;
use indicatif::{ProgressBar, ProgressStyle};
use lobe::verify::Pcg32;
use lobe::{Vec2, Vec3};
use rayon::prelude::*;
use std::sync::atomic::{AtomicU64, Ordering};

/// What to render.
#[derive(Clone, Copy, Debug)]
pub struct RenderSettings {
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// Samples per pixel.
    pub spp: u32,
    /// The seed of every pixel's generator.
    pub seed: u64,
}

/// A rendered image: linear radiance per pixel, rows from the top.
pub struct Film {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// The pixel means, row-major.
    pub pixels: Vec<Vec3>,
    /// Samples that came out NaN or infinite and were dropped (a bug if not zero).
    pub dropped: u64,
}

/// One radiance sample of pixel `(x, y)`: a ray through a uniformly jittered point of the
/// pixel (a box filter).
#[inline]
pub fn sample_pixel(
    scene: &Scene,
    integrator: &Integrator,
    settings: &RenderSettings,
    x: u32,
    y: u32,
    rng: &mut Pcg32,
) -> Vec3 {
    let jitter = rng.next_vec2();
    let film = Vec2::new(
        (x as f32 + jitter.x) / settings.width as f32,
        (y as f32 + jitter.y) / settings.height as f32,
    );
    integrator.radiance(scene, scene.camera.ray(film), rng)
}

/// The generator of pixel `(x, y)`.
pub fn rng_for(settings: &RenderSettings, x: u32, y: u32) -> Pcg32 {
    pixel_rng(
        settings.seed,
        u64::from(y) * u64::from(settings.width) + u64::from(x),
    )
}

/// Runs `work` on a pool of `threads` worker threads (`None`: one per core, or what
/// `RAYON_NUM_THREADS` says): [`render`] inside it renders on those threads.
///
/// # Errors
/// A message if the threads cannot be started, or `work`'s own.
pub fn with_threads<T: Send>(
    threads: Option<u32>,
    work: impl FnOnce() -> Result<T, String> + Send,
) -> Result<T, String> {
    let mut pool = rayon::ThreadPoolBuilder::new();
    if let Some(n) = threads {
        pool = pool.num_threads(n as usize);
    }
    let pool = pool
        .build()
        .map_err(|e| format!("cannot start the worker threads: {e}"))?;
    pool.install(work)
}

/// Renders the scene, rows in parallel, showing a progress bar when `progress` is set.
pub fn render(
    scene: &Scene,
    integrator: &Integrator,
    settings: &RenderSettings,
    progress: bool,
) -> Film {
    let (w, h) = (settings.width, settings.height);
    let bar = if progress {
        let bar = ProgressBar::new(u64::from(h));
        if let Ok(style) = ProgressStyle::with_template(
            "{spinner} [{elapsed_precise}] {wide_bar} {pos}/{len} rows, eta {eta}",
        ) {
            bar.set_style(style);
        }
        bar
    } else {
        ProgressBar::hidden()
    };
    let dropped = AtomicU64::new(0);
    let mut pixels = vec![Vec3::ZERO; w as usize * h as usize];
    pixels
        .par_chunks_mut(w as usize)
        .enumerate()
        .for_each(|(y, row)| {
            let y = y as u32;
            let mut bad = 0;
            for (x, px) in row.iter_mut().enumerate() {
                let x = x as u32;
                let mut rng = rng_for(settings, x, y);
                let mut sum = Vec3::ZERO;
                for _ in 0..settings.spp {
                    let l = sample_pixel(scene, integrator, settings, x, y, &mut rng);
                    if l.is_finite() {
                        sum += l;
                    } else {
                        bad += 1;
                    }
                }
                *px = sum / settings.spp as f32;
            }
            dropped.fetch_add(bad, Ordering::Relaxed);
            bar.inc(1);
        });
    bar.finish_and_clear();
    Film {
        width: w,
        height: h,
        pixels,
        dropped: dropped.into_inner(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::path::PathTracer;
    use crate::scenes::SceneChoice;

    /// A render is the same on any number of threads: every pixel has its own generator.
    #[test]
    fn threads_do_not_change_the_image() {
        let (scene, _) = SceneChoice::Lights.build(16.0 / 9.0).unwrap();
        let integrator = Integrator::Path(PathTracer {
            max_depth: 6,
            filter: None,
            irradiance: false,
            clamp: None,
            roulette: true,
        });
        let settings = RenderSettings {
            width: 32,
            height: 18,
            spp: 4,
            seed: 9,
        };
        let on = |n| {
            with_threads(Some(n), || {
                assert_eq!(rayon::current_num_threads(), n as usize);
                Ok(render(&scene, &integrator, &settings, false).pixels)
            })
            .unwrap()
        };
        assert_eq!(on(1), on(3));
    }
}
