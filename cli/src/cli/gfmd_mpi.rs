//! `mpirun -np N asperity gfmd …` (feature `mpi`): the run, load sweep or load cycle on N MPI
//! ranks ([`asperity::gfmd::distributed`]), rank 0 printing what the serial run prints.
//!
//! Built without the feature, or started as one process, `gfmd` runs serially as always. On
//! N > 1 ranks: single runs, load sweeps (`--from/--to`, upwards or downwards) and the load
//! cycle (`--cycle`), generated or `--surface` maps, every output format; `--extrapolate`,
//! `--seeds K > 1` and `--save-surface` run on one process only (no rank holds the map). The
//! hard wall relaxes with FIRE on ranks (Polonsky–Keer is not distributed): the output equals
//! the serial `--method fire` run, and with adhesion the serial run whatever the method.

use super::gfmd::GfmdArgs;
use asperity::error::Result;

/// Runs `gfmd` on the MPI ranks when there are several: `Some(result)` (rank 0's; the other
/// ranks print nothing and return Ok), `None` to run serially.
#[cfg(not(feature = "mpi"))]
pub fn on_ranks(_args: &GfmdArgs) -> Option<Result<()>> {
    None
}

/// Runs `gfmd` on the MPI ranks when there are several: `Some(result)` (rank 0's; the other
/// ranks print nothing and return Ok), `None` to run serially.
#[cfg(feature = "mpi")]
pub fn on_ranks(args: &GfmdArgs) -> Option<Result<()>> {
    use asperity::gfmd::distributed::mpi_comm::MpiComm;
    use asperity::gfmd::distributed::Comm;
    let comm = MpiComm::init()?;
    if comm.size() == 1 {
        return None;
    }
    let root = comm.rank() == 0;
    let result = distributed::run(&comm, args);
    // MPI is finalised here, before the process exits
    drop(comm);
    Some(if root { result } else { Ok(()) })
}

#[cfg(feature = "mpi")]
mod distributed {
    use super::super::emit;
    use super::super::gfmd::{job, path_output, setup, GfmdArgs, MethodArg};
    use asperity::error::{Error, Result};
    use asperity::gfmd::distributed::{run_on_ranks, Comm};
    use std::sync::atomic::AtomicBool;

    pub fn run(comm: &dyn Comm, args: &GfmdArgs) -> Result<()> {
        let root = comm.rank() == 0;
        for (flag, on, value) in [
            ("--extrapolate", args.extrapolate, "set".to_string()),
            ("--seeds", args.seeds > 1, args.seeds.to_string()),
            (
                "--save-surface",
                args.save_surface.is_some(),
                args.save_surface
                    .as_ref()
                    .map_or(String::new(), |p| p.display().to_string()),
            ),
        ] {
            if on {
                return Err(Error::field(
                    flag,
                    value,
                    format!("unset on {} MPI ranks (it runs on one process)", comm.size()),
                ));
            }
        }
        let (setup, opts) = setup(args)?;
        if root && setup.scene.surface_energy_j_m2() == 0.0 && args.method == MethodArg::Auto {
            eprintln!(
                "asperity gfmd: note: on {} ranks the hard wall relaxes with FIRE (Polonsky-Keer is not distributed)",
                comm.size()
            );
        }
        let out = run_on_ranks(comm, &setup, job(args), &opts, &mut |_, _| {}, &AtomicBool::new(false))?;
        if root {
            emit(&path_output(out, args.format));
        }
        Ok(())
    }
}
