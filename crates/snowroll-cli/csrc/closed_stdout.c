/*
 * Whether standard output was closed when the program started (`>&-`).
 *
 * Rust's runtime puts /dev/null, opened for reading and writing, in place of
 * a closed descriptor 0 to 2 before `main` runs, so from `main` on a closed
 * stdout cannot be told from a read-write /dev/null (Python's
 * subprocess.DEVNULL, a daemon's stdio), which must work. A constructor runs
 * before the runtime: it looks at descriptor 1 and, when it is closed, leaves
 * a mark in the environment, which `console::note_start` reads and removes
 * (no Rust code here: the workspace forbids `unsafe`, and the environment is
 * a channel that needs none). Written in C because Rust offers no way to run
 * code before its own runtime without `unsafe`.
 */
#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>

__attribute__((constructor)) static void snowroll_note_closed_stdout(void) {
    if (fcntl(1, F_GETFD) == -1 && errno == EBADF) {
        setenv("SNOWROLL_STDOUT_CLOSED_AT_START", "1", 1);
    }
}
