//! Library callers with several threads: a clear error, never an abort (symbolica's
//! restricted mode aborts the process when a second thread uses it while the first is alive).

use std::sync::mpsc;

const SPEC: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/derivations/regulateur_centrifuge.json"
);

fn load_on_new_thread() -> Result<usize, String> {
    std::thread::spawn(|| {
        torseur::spec::load(SPEC)
            .map(|m| m.bodies().len())
            .map_err(|e| e.to_string())
    })
    .join()
    .unwrap()
}

#[test]
fn a_second_thread_gets_a_clear_error_while_the_first_is_alive() {
    if std::env::var_os("SYMBOLICA_LICENSE").is_some() {
        return; // licensed: several threads are allowed, nothing to refuse
    }
    // This test's own thread never uses symbolica; thread A does, and stays alive until B
    // has tried.
    let (tried_tx, tried_rx) = mpsc::channel::<()>();
    let (loaded_tx, loaded_rx) = mpsc::channel::<()>();
    let a = std::thread::spawn(move || {
        let m = torseur::spec::load(SPEC).unwrap();
        loaded_tx.send(()).unwrap();
        tried_rx.recv().unwrap();
        torseur::derive(&m, &m.quantities()[0]).is_ok()
    });
    loaded_rx.recv().unwrap();
    let b = load_on_new_thread();
    tried_tx.send(()).unwrap();
    assert!(a.join().unwrap(), "the owning thread keeps working");
    let err = b.unwrap_err();
    assert!(err.contains("one thread at a time"), "{err}");
    // Once A has exited, another thread may use torseur (threads one after another are fine).
    assert_eq!(load_on_new_thread(), Ok(2));
}
