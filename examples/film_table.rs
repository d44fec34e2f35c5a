//! Writes the finite film's table (`src/joint/film_table.bin`, docs in
//! `flexible_slider_crank::joint::finite_film`): at every node of length-to-diameter ratio,
//! eccentricity ratio and squeeze direction, the finite-difference Reynolds solution with the
//! Reynolds cavitation condition as ratios to the short film. The λ nodes are shared among the
//! machine's cores; about 20 minutes on 2 cores.
//!
//! `cargo run --release --example film_table [OUTPUT]`

use std::error::Error;
use std::sync::atomic::{AtomicUsize, Ordering};

use flexible_slider_crank::joint::finite_film::{
    DIRECTION_NODES, ECCENTRICITY_NODES, RATIO_NODES, RATIOS, direction_node, eccentricity_node,
    ratio_node, ratios, table_bytes,
};
use flexible_slider_crank::joint::reynolds::Workspace;

/// The ratios at every (ε, ψ) node of λ node `k`, ε ascending and ψ back and forth so that each
/// solve starts from its neighbour's field.
fn plane(k: usize, done: &AtomicUsize) -> Vec<[f64; RATIOS]> {
    let lambda = ratio_node(k);
    let mut work = Workspace::default();
    let mut out = vec![[0.0; RATIOS]; ECCENTRICITY_NODES * DIRECTION_NODES];
    for i in 0..ECCENTRICITY_NODES {
        for step in 0..DIRECTION_NODES {
            let j = if i % 2 == 0 {
                step
            } else {
                DIRECTION_NODES - 1 - step
            };
            out[i * DIRECTION_NODES + j] =
                ratios(lambda, eccentricity_node(i), direction_node(j), &mut work);
        }
        let n = done.fetch_add(DIRECTION_NODES, Ordering::Relaxed) + DIRECTION_NODES;
        eprint!(
            "\r{n} of {} nodes",
            RATIO_NODES * ECCENTRICITY_NODES * DIRECTION_NODES
        );
    }
    out
}

fn main() -> Result<(), Box<dyn Error>> {
    let output = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "src/joint/film_table.bin".into());
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let next = AtomicUsize::new(0);
    let done = AtomicUsize::new(0);
    let mut planes: Vec<(usize, Vec<[f64; RATIOS]>)> = std::thread::scope(|scope| {
        let workers: Vec<_> = (0..threads)
            .map(|_| {
                scope.spawn(|| {
                    let mut mine = Vec::new();
                    // the longest bearings (largest grids) first
                    loop {
                        let n = next.fetch_add(1, Ordering::Relaxed);
                        if n >= RATIO_NODES {
                            break mine;
                        }
                        let k = RATIO_NODES - 1 - n;
                        mine.push((k, plane(k, &done)));
                    }
                })
            })
            .collect();
        workers
            .into_iter()
            .flat_map(|w| w.join().unwrap_or_default())
            .collect()
    });
    eprintln!();
    if planes.len() != RATIO_NODES {
        return Err("a worker failed".into());
    }
    planes.sort_by_key(|(k, _)| *k);
    let values: Vec<[f64; RATIOS]> = planes.into_iter().flat_map(|(_, p)| p).collect();
    std::fs::write(&output, table_bytes(&values))?;
    eprintln!("wrote {output}");
    Ok(())
}
