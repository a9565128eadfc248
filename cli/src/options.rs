//! The options several subcommands share, defined once (`#[command(flatten)]`).

use std::num::ParseIntError;
use std::path::PathBuf;
use std::str::FromStr;

use clap::Args;

/// `--root`: where a scenario's paths start.
#[derive(Debug, Clone, Args)]
pub struct RootOption {
    /// The folder the scenario's paths are relative to.
    #[arg(long)]
    pub root: Option<PathBuf>,
}

/// `--size`: the frame drawn.
#[derive(Debug, Clone, Copy, Args)]
pub struct SizeOption {
    /// Frame size in pixels, WIDTHxHEIGHT.
    #[arg(long, default_value = "1200x800", value_parser = parse_size)]
    pub size: (u32, u32),
}

/// An option's value that is not the pair of numbers it should be.
#[derive(Debug, thiserror::Error)]
pub enum PairError {
    /// No separator.
    #[error("`{text}`: expected {shape}")]
    Shape {
        /// The value given.
        text: String,
        /// What was expected, with an example.
        shape: &'static str,
    },
    /// A part that is not a whole number.
    #[error("`{text}`: {source}")]
    Number {
        /// The value given.
        text: String,
        /// Why.
        source: ParseIntError,
    },
}

/// Two whole numbers separated by `separator`.
fn parse_pair<T: FromStr<Err = ParseIntError>>(
    text: &str,
    separator: char,
    shape: &'static str,
) -> Result<(T, T), PairError> {
    let (a, b) = text.split_once(separator).ok_or_else(|| PairError::Shape {
        text: text.to_owned(),
        shape,
    })?;
    let n = |t: &str| {
        t.trim().parse::<T>().map_err(|source| PairError::Number {
            text: text.to_owned(),
            source,
        })
    };
    Ok((n(a)?, n(b)?))
}

/// `WIDTHxHEIGHT`.
pub fn parse_size(text: &str) -> Result<(u32, u32), PairError> {
    parse_pair(text, 'x', "WIDTHxHEIGHT, e.g. 1200x800")
}

/// `X,Y`.
pub fn parse_cell(text: &str) -> Result<(i64, i64), PairError> {
    parse_pair(text, ',', "X,Y, e.g. 30,40")
}
