//! The `asperity` binary: a thin wrapper around [`asperity_cli::cli`].

fn main() {
    std::process::exit(asperity_cli::cli::main());
}
