//! The thread that builds the pages: the first at once, then one whenever the problem file
//! changes. It only ever looks at the file's metadata between builds, so a FIFO or a
//! device put in the file's place cannot block it; the build itself reads the file only
//! when it is a regular file of bounded size (`problem::load_file`), and shows the reason
//! on the page otherwise.

use super::{page, Shown};
use crate::cli::MethodArg;
use std::path::Path;
use std::sync::Arc;
use std::time::{Duration, SystemTime};

/// How often the problem file is looked at.
pub(crate) const POLL: Duration = Duration::from_millis(50);

/// The file's identity and state: a change in any of them is an edit.
type Stamp = Option<(SystemTime, u64, u64, u64)>;

fn stamp(path: &Path) -> Stamp {
    use std::os::unix::fs::MetadataExt;
    let meta = std::fs::metadata(path).ok()?;
    Some((meta.modified().ok()?, meta.len(), meta.ino(), meta.dev()))
}

/// Builds the first page, then a new one whenever the file changes, for as long as
/// someone holds the receiving end of `news`.
pub(crate) fn build_and_watch(
    path: &Path,
    method: MethodArg,
    news: &tokio::sync::watch::Sender<Shown>,
) {
    let mut last = stamp(path);
    publish(news, page::page(path, method));
    while !news.is_closed() {
        std::thread::sleep(POLL);
        let now = stamp(path);
        if now == last {
            continue;
        }
        last = now;
        news.send_modify(|s| s.building = true);
        publish(news, page::page(path, method));
    }
}

fn publish(news: &tokio::sync::watch::Sender<Shown>, page: String) {
    news.send_modify(|s| {
        s.page = Arc::from(page);
        s.version += 1;
        s.building = false;
    });
}
