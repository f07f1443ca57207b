//! The guard that keeps symbolica on one thread: its restricted mode aborts the process when
//! a second thread uses it.

use super::ExprError;

/// How long a thread waits for another to finish with symbolica before getting an error.
const THREAD_WAIT: std::time::Duration = std::time::Duration::from_secs(2);

/// The thread that uses symbolica in this process, if any.
static OWNER: std::sync::Mutex<Option<std::thread::ThreadId>> = std::sync::Mutex::new(None);

/// Releases the ownership when the owning thread exits.
struct OwnerMark;

impl Drop for OwnerMark {
    fn drop(&mut self) {
        let me = std::thread::current().id();
        let mut owner = OWNER.lock().unwrap_or_else(|p| p.into_inner());
        if *owner == Some(me) {
            *owner = None;
        }
    }
}

thread_local! {
    static MARK: OwnerMark = const { OwnerMark };
}

/// One thread at a time may use symbolica: its restricted mode aborts the process when a
/// second thread uses it while the first is alive (threads one after another are fine). The
/// first thread that creates a registry owns symbolica until it exits; another thread then
/// gets a clear error instead of an abort. Registries and expressions are `!Send` and `!Sync`,
/// so they never migrate. With `SYMBOLICA_LICENSE` set the limit does not apply.
#[derive(Debug)]
pub(super) struct ThreadGuard {
    pub(super) _not_send: std::marker::PhantomData<*const ()>,
}

impl ThreadGuard {
    pub(super) fn acquire() -> Result<ThreadGuard, ExprError> {
        let guard = ThreadGuard {
            _not_send: std::marker::PhantomData,
        };
        if std::env::var_os("SYMBOLICA_LICENSE").is_some() {
            return Ok(guard);
        }
        let me = std::thread::current().id();
        // A thread that has just finished releases symbolica in its exit destructors: wait a
        // little for that before refusing (serialised hand-over between threads).
        let start = std::time::Instant::now();
        let mut owner = OWNER.lock().unwrap_or_else(|p| p.into_inner());
        while owner.is_some_and(|id| id != me) && start.elapsed() < THREAD_WAIT {
            drop(owner);
            std::thread::sleep(std::time::Duration::from_millis(1));
            owner = OWNER.lock().unwrap_or_else(|p| p.into_inner());
        }
        match *owner {
            Some(id) if id == me => {}
            Some(id) => {
                return Err(ExprError::Thread(format!(
                    "thread {me:?} cannot use torseur while thread {id:?} is using it: \
                     unlicensed symbolica allows one thread at a time (use torseur from one \
                     thread, let the other thread finish first, or set SYMBOLICA_LICENSE)"
                )));
            }
            None => {
                *owner = Some(me);
                MARK.with(|_| {});
            }
        }
        Ok(guard)
    }
}
