"""Files that appear whole or not at all.

Every file the Python side writes (CSV tables, .pvd collections, run markers, reports, batch summaries,
pictures) is written under a temporary name beside its target, flushed to the disk (fsync, which also
reports a write the kernel deferred and then could not make) and renamed over the target. On any error the
temporary is removed, the old file stays as it was, and the error (an OSError) names the target.
"""
import contextlib
import os
import re


def _alive(pid):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


def remove_stale(folder, pattern):
    """Removes the entries of 'folder' whose name matches 'pattern' (a compiled expression whose first group
    is a process id) and whose process is gone: what a killed run left (files or folders)."""
    import shutil
    try:
        names = os.listdir(folder or ".")
    except OSError:
        names = []
    for name in names:
        m = pattern.match(name)
        if m and int(m.group(1)) != os.getpid() and not _alive(int(m.group(1))):
            path = os.path.join(folder, name)
            try:
                shutil.rmtree(path) if os.path.isdir(path) and not os.path.islink(path) else os.remove(path)
            except OSError:
                pass


def temporary_path(folder, stem, ext):
    """A temporary file name beside the target (".STEM.tmpPID EXT"), after removing those a killed run of
    another process left for the same target."""
    remove_stale(folder, re.compile(r"^\.%s\.tmp(\d+)(_\d+)?%s$" % (re.escape(stem), re.escape(ext))))
    return os.path.join(folder, ".%s.tmp%d%s" % (stem, os.getpid(), ext))


def _sync(path, flags=os.O_RDONLY):
    fd = os.open(path, flags)
    try:
        os.fsync(fd)
    finally:
        os.close(fd)


@contextlib.contextmanager
def replacing(path):
    """Yields a temporary path beside 'path' for the caller to write; when the block ends without an error,
    the temporary is flushed to the disk and renamed over 'path'. On an error the temporary is removed and
    'path' is untouched; an OSError is raised again with 'path' as its file name."""
    folder, base = os.path.split(os.path.abspath(path))
    stem, ext = os.path.splitext(base)
    tmp = temporary_path(folder, stem, ext)
    try:
        yield tmp
        _sync(tmp)
        os.replace(tmp, path)
        try:
            _sync(folder, os.O_RDONLY | os.O_DIRECTORY)
        except OSError:
            pass  # the rename is made; some file systems do not sync folders
    except OSError as e:
        raise OSError(e.errno, e.strerror or str(e), path) from None
    finally:
        if os.path.lexists(tmp):
            os.remove(tmp)


def write_text(path, text):
    """Write text (UTF-8) so that the file appears whole or not at all."""
    with replacing(path) as tmp:
        with open(tmp, "w", encoding="utf-8") as f:
            f.write(text)
