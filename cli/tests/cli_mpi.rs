//! `mpirun -np N asperity gfmd …` (feature `mpi`) prints what the serial run prints, bit for
//! bit: adhesive and not, half-space and slab, a single run, a load sweep and the load cycle
//! to pull-off, on 1, 2 and 4 ranks (4 oversubscribed on a 2-core machine). Needs `mpirun` (MPICH or OpenMPI) on PATH.
//! The serial reference is the same binary started without `mpirun` (one process: the serial
//! solver); the hard wall is compared with `--method fire`, the solver the ranks use.

#![cfg(feature = "mpi")]

use std::process::Command;

/// `asperity ARGS` on `np` MPI ranks (None: one plain process); the JSON on stdout without
/// its wall times.
fn run(np: Option<usize>, args: &[&str]) -> serde_json::Value {
    let bin = env!("CARGO_BIN_EXE_asperity");
    let mut cmd = match np {
        None => Command::new(bin),
        Some(n) => {
            let mut c = Command::new("mpirun");
            let open_mpi = Command::new("mpirun")
                .arg("--version")
                .output()
                .map(|o| String::from_utf8_lossy(&o.stdout).contains("Open MPI"))
                .unwrap_or(false);
            if open_mpi {
                c.arg("--oversubscribe");
            }
            c.args(["-np", &n.to_string(), bin]);
            c
        }
    };
    // OpenMPI refuses root without these; one thread per rank on a small machine
    let out = cmd
        .args(args)
        .env("OMPI_ALLOW_RUN_AS_ROOT", "1")
        .env("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
        .env("RAYON_NUM_THREADS", "1")
        .output()
        .expect("mpirun (MPICH or OpenMPI) on PATH");
    assert!(
        out.status.success(),
        "{np:?} ranks, {args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    let mut v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("one JSON document");
    for k in ["elapsed_s", "solve_elapsed_s", "theory_elapsed_s"] {
        v.as_object_mut().unwrap().remove(k);
    }
    v
}

#[test]
fn gfmd_on_mpi_ranks_prints_the_serial_json() {
    let cases: [&[&str]; 5] = [
        // adhesive, half-space
        &[
            "gfmd",
            "--preset",
            "system-2",
            "--grid",
            "64",
            "--pressure",
            "0.02",
            "--method",
            "fire",
            "--bins",
            "40",
        ],
        // hard wall, slab
        &[
            "gfmd",
            "--preset",
            "system-1",
            "--gamma",
            "0",
            "--grid",
            "64",
            "--pressure",
            "0.05",
            "--thickness",
            "1",
            "--method",
            "fire",
        ],
        // adhesive load sweep (warm starts)
        &[
            "gfmd", "--preset", "system-2", "--grid", "64", "--from", "0.01", "--to", "0.04", "--points", "3",
            "--method", "fire",
        ],
        // adhesive load cycle to pull-off, half-space and slab
        &[
            "gfmd", "--preset", "system-2", "--grid", "32", "--cycle", "--from", "0.003", "--to", "0.02", "--points",
            "2",
        ],
        &[
            "gfmd",
            "--preset",
            "system-2",
            "--grid",
            "32",
            "--cycle",
            "--from",
            "0.003",
            "--to",
            "0.02",
            "--points",
            "2",
            "--thickness",
            "0.5",
        ],
    ];
    // CI runs `-np 2` only (ASPERITY_MPI_RANKS=2)
    let ranks: Vec<usize> = match std::env::var("ASPERITY_MPI_RANKS") {
        Ok(s) => s.split(',').map(|x| x.trim().parse().expect("ranks")).collect(),
        Err(_) => vec![1, 2, 4],
    };
    for args in cases {
        let serial = run(None, args);
        let grid = args[args.iter().position(|a| *a == "--grid").unwrap() + 1];
        assert_eq!(
            serial.get("grid").and_then(|g| g.as_u64()),
            grid.parse().ok(),
            "{serial}"
        );
        if args.contains(&"--cycle") {
            assert!(serial["pull_off_bracket"].is_array(), "a bisected pull-off: {serial}");
        }
        for &np in &ranks {
            assert_eq!(run(Some(np), args), serial, "{np} ranks: {args:?}");
        }
    }
}
