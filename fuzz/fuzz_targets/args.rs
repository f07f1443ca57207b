//! The CLI's argument handling: any argument list (NUL-separated words) is parsed by the
//! binary's own clap definitions; parsing and the checks that need no work (the time limit)
//! never panic, and an accepted time limit is a finite positive duration.
#![no_main]
use clap::Parser;
use libfuzzer_sys::fuzz_target;

#[allow(dead_code)]
#[path = "../../src/bin/torseur/args.rs"]
mod args;

fuzz_target!(|data: &[u8]| {
    let Ok(s) = std::str::from_utf8(data) else {
        return;
    };
    let words = std::iter::once("torseur").chain(s.split('\0'));
    if let Ok(cli) = args::Cli::try_parse_from(words)
        && let Some(t) = cli.timeout
        && let Ok(d) = args::time_limit(t)
    {
        assert!(d.as_secs_f64() > 0.0 && d.as_secs_f64() <= args::MAX_TIMEOUT);
    }
});
