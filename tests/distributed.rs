//! GFMD over ranks equals the serial run bit for bit (src/gfmd/distributed): ranks as threads
//! ([`ThreadComm`]) for 1–4 ranks, against the serial library on the same setup. The MPI
//! transport runs the same code (tests/mpi.rs, feature `mpi`).

use asperity::gfmd::distributed::map::{self, Slab};
use asperity::gfmd::distributed::slab_fft::SlabFft;
use asperity::gfmd::distributed::{run_on_ranks, Comm, Job, Outcome, ThreadComm};
use asperity::gfmd::{self, GfmdOptions, GfmdSetup, GridSpec, Method};
use asperity::input::preset::Preset;
use asperity::numerics::fft2::RealFft2;
use asperity::surface::heightmap;
use asperity::surface::spectrum::Spectrum;
use rustfft::num_complex::Complex64;
use std::sync::atomic::AtomicBool;

fn setup(preset: &str, grid: usize, pressure: f64, adhesive: bool, thickness_qr: f64) -> GfmdSetup {
    let p = Preset::resolve(preset).unwrap();
    let mut scene = p.scene().unwrap().with_pressure(pressure).unwrap();
    if !adhesive {
        scene = scene.without_adhesion();
    }
    scene = scene.with_thickness_qr(thickness_qr).unwrap();
    GfmdSetup {
        scene,
        grid: GridSpec::from_preset(p.gfmd.as_ref().unwrap()).with_grid(grid).unwrap(),
        seed: 3,
        surface: None,
        rescale: true,
    }
}

/// The JSON of a result without its wall times.
fn json(r: &gfmd::GfmdResult) -> serde_json::Value {
    let mut v = serde_json::to_value(r).unwrap();
    for k in ["elapsed_s", "solve_elapsed_s", "theory_elapsed_s"] {
        v.as_object_mut().unwrap().remove(k);
    }
    v
}

#[test]
fn slab_fft_convolution_equals_the_serial_one_bit_for_bit() {
    for (nx, ny) in [(12, 10), (7, 5), (64, 64), (130, 66)] {
        let h: Vec<f64> = (0..nx * ny).map(|k| (((k * 7919) % 13) as f64 - 6.0) * 0.1).collect();
        let mut plan = RealFft2::new(nx, ny);
        let nh = plan.nh();
        let kernel: Vec<f64> = (0..nh * ny).map(|k| 1.0 + (k % 7) as f64 * 0.25).collect();
        let mut spec = vec![Complex64::new(0.0, 0.0); nh * ny];
        let mut want = vec![0.0; nx * ny];
        plan.convolve(&h, &plan.kernel(&kernel), &mut spec, &mut want);
        for ranks in 1..=4 {
            let got: Vec<Vec<f64>> = ThreadComm::run(ranks, |c| {
                let mut f = SlabFft::new(nx, ny, c.rank(), c.size());
                let (y0, y1) = f.my_rows();
                let (c0, c1) = f.my_cols();
                // the kernel in the rank's column layout
                let mut k = vec![0.0; (c1 - c0) * ny];
                for kx in c0..c1 {
                    for ky in 0..ny {
                        k[(kx - c0) * ny + ky] = kernel[ky * nh + kx];
                    }
                }
                let mut s = vec![Complex64::new(0.0, 0.0); f.local_spectrum_len()];
                let mut out = vec![0.0; (y1 - y0) * nx];
                f.convolve(c, &h[y0 * nx..y1 * nx], &k, &mut s, &mut out);
                out
            });
            assert_eq!(got.concat(), want, "{nx}x{ny} on {ranks} ranks");
        }
    }
}

#[test]
fn the_map_and_its_moments_by_slabs_equal_the_serial_ones() {
    let s = setup("system-2", 96, 0.01, true, f64::INFINITY);
    let (red, _) = asperity::gfmd::reduction::reduce(&s.scene, &s.grid, true).unwrap();
    let Spectrum::SelfAffine(spec) = red.spectrum().clone() else {
        unreachable!()
    };
    let whole = heightmap::generate(&spec, 96, 3).unwrap();
    let serial_d = whole.discrete_spectrum(spec.q_r()).unwrap();
    for ranks in [1, 2, 3, 4] {
        let parts: Vec<(Slab, f64, f64, bool)> = ThreadComm::run(ranks, |c| {
            let slab = map::generate(c, &spec, 96, 3).unwrap();
            let mut f = SlabFft::new(96, 96, c.rank(), c.size());
            let g = map::rms_gradient(c, &mut f, &slab);
            let h = map::rms_height(c, &slab);
            let d = map::discrete_spectrum(c, &slab, spec.q_r()).unwrap();
            (slab, g, h, d == serial_d)
        });
        let heights: Vec<f64> = parts.iter().flat_map(|p| p.0.heights.clone()).collect();
        assert_eq!(heights, whole.heights, "{ranks} ranks");
        for p in &parts {
            assert_eq!(p.1, whole.rms_gradient());
            assert_eq!(p.2, whole.rms_height());
            assert!(p.3, "discrete spectrum on {ranks} ranks");
        }
    }
}

/// Adhesive and not, half-space and slab: the JSON of rank 0 equals the serial run's (FIRE)
/// exactly, on 1 to 4 ranks (3: slabs that do not align with FIRE's 4096-node chunks).
#[test]
fn a_run_over_ranks_equals_the_serial_run_bit_for_bit() {
    let opts = GfmdOptions {
        method: Method::Fire,
        pr_bins: 50,
        ..GfmdOptions::default()
    };
    let no = AtomicBool::new(false);
    for (preset, grid, p, adh, t) in [
        ("system-2", 64, 0.02, true, f64::INFINITY),
        ("system-1", 128, 0.05, false, f64::INFINITY),
        ("system-1", 80, 0.05, false, 1.0),
        ("system-2", 128, 0.01, true, 0.5),
    ] {
        let s = setup(preset, grid, p, adh, t);
        let serial = json(&gfmd::run(&s, &opts, &mut |_| {}, &no).unwrap());
        for ranks in [1, 2, 3, 4] {
            let got = ThreadComm::run(ranks, |c| {
                match run_on_ranks(c, &s, Job::Run, &opts, &mut |_, _| {}, &no) {
                    Ok(Outcome::Run(r)) => *r,
                    o => panic!("{o:?}"),
                }
            });
            assert_eq!(
                json(&got[0]),
                serial,
                "{preset} {grid}^2 adhesive {adh} t*q_r {t} on {ranks} ranks"
            );
            for r in &got[1..] {
                assert_eq!(r.stats, got[0].stats);
                assert_eq!(r.iterations, got[0].iterations);
            }
        }
    }
}

/// A load sweep (warm starts) over ranks equals the serial sweep, rows and theory.
#[test]
fn a_load_sweep_over_ranks_equals_the_serial_sweep_bit_for_bit() {
    use asperity::theory::sweep::SweepSpec;
    let opts = GfmdOptions {
        method: Method::Fire,
        ..GfmdOptions::default()
    };
    let no = AtomicBool::new(false);
    let spec = SweepSpec {
        from: 0.01,
        to: 0.05,
        points: 3,
    };
    for adh in [false, true] {
        let s = setup("system-2", 64, 0.01, adh, f64::INFINITY);
        let mut serial =
            serde_json::to_value(gfmd::sweep::run_sweep(&s, &spec, &opts, &mut |_, _| {}, &no).unwrap()).unwrap();
        serial.as_object_mut().unwrap().remove("elapsed_s");
        for ranks in [2, 3] {
            let got = ThreadComm::run(ranks, |c| {
                match run_on_ranks(c, &s, Job::Sweep(spec), &opts, &mut |_, _| {}, &no) {
                    Ok(Outcome::Sweep(sw)) => *sw,
                    o => panic!("{o:?}"),
                }
            });
            let mut v = serde_json::to_value(&got[0]).unwrap();
            v.as_object_mut().unwrap().remove("elapsed_s");
            assert_eq!(v, serial, "adhesive {adh} on {ranks} ranks");
        }
    }
}

/// The load cycle over ranks (loading, unloading, tension, the bisected pull-off) equals the
/// serial cycle bit for bit: adhesive half-space and slab, and a hard-wall slab (FIRE).
#[test]
fn a_load_cycle_over_ranks_equals_the_serial_cycle_bit_for_bit() {
    use asperity::gfmd::cycle::{run_cycle, CycleSpec};
    let opts = GfmdOptions {
        method: Method::Fire,
        ..GfmdOptions::default()
    };
    let no = AtomicBool::new(false);
    let spec = CycleSpec {
        from: 0.003,
        to: 0.02,
        points: 2,
        cycle: true,
    };
    let without_time = |c: &asperity::gfmd::cycle::GfmdCycle| {
        let mut v = serde_json::to_value(c).unwrap();
        v.as_object_mut().unwrap().remove("elapsed_s");
        v
    };
    for (adh, t) in [(true, f64::INFINITY), (true, 0.5), (false, 0.5)] {
        let s = setup("system-2", 32, 0.01, adh, t);
        let serial = run_cycle(&s, &spec, &opts, &mut |_, _| {}, &no).unwrap();
        if adh {
            assert!(serial.pull_off_bracket.is_some(), "t·q_r {t}: a bisected pull-off");
        }
        let serial = without_time(&serial);
        for ranks in [1, 2, 3, 4] {
            let got = ThreadComm::run(ranks, |c| {
                match run_on_ranks(c, &s, Job::Cycle(spec), &opts, &mut |_, _| {}, &no) {
                    Ok(Outcome::Cycle(cy)) => *cy,
                    o => panic!("{o:?}"),
                }
            });
            assert_eq!(
                without_time(&got[0]),
                serial,
                "adhesive {adh} t·q_r {t} on {ranks} ranks"
            );
            for r in &got[1..] {
                assert_eq!(r.rows, got[0].rows);
                assert_eq!(r.pull_off_pressure, got[0].pull_off_pressure);
            }
        }
    }
}
