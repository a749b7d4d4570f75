//! The baseline for benches/report-100k.sh: read a TOML file and
//! deserialize it with the toml crate alone, nothing else.
//!
//!     cargo run --release --example toml_only [--borrowed] FILE
//!
//! By default the file is deserialized into a generic `toml::Table` (owned
//! strings, `toml::Value` tree): what "the toml crate alone takes to
//! deserialize that file" means for a program that does not know its
//! structure. `--borrowed` stops at the crate's own parse tree,
//! `toml::de::DeTable` (strings and numbers borrowed from the input, not yet
//! converted), which every `toml::from_str` builds first: a lower bound for
//! any use of the crate's deserializer.
//!
//! Prints one line (the number of top-level keys and of `[[part]]` tables)
//! so the work cannot be optimised away; exits 2 on a parse error.

use std::process::ExitCode;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (borrowed, path) = match args.as_slice() {
        [p] => (false, p),
        [flag, p] if flag == "--borrowed" => (true, p),
        _ => {
            eprintln!("usage: toml_only [--borrowed] FILE");
            return ExitCode::from(2);
        }
    };
    let text = match std::fs::read_to_string(path) {
        Ok(t) => t,
        Err(e) => {
            eprintln!("error: cannot read {path}: {e}");
            return ExitCode::from(2);
        }
    };
    let counts = if borrowed {
        toml::de::DeTable::parse(&text).map(|root| {
            let root = root.into_inner();
            let parts = match root.get("part").map(|v| v.get_ref()) {
                Some(toml::de::DeValue::Array(a)) => a.len(),
                _ => 0,
            };
            (root.len(), parts)
        })
    } else {
        toml::from_str::<toml::Table>(&text).map(|root| {
            let parts = root
                .get("part")
                .and_then(toml::Value::as_array)
                .map_or(0, Vec::len);
            (root.len(), parts)
        })
    };
    match counts {
        Ok((keys, parts)) => {
            println!("{keys} top-level keys, {parts} parts");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprint!("error: {path}: {e}");
            ExitCode::from(2)
        }
    }
}
