//! The `asperity` binary: a thin wrapper around [`asperity::cli`].

fn main() {
    std::process::exit(asperity::cli::main());
}
