"""Seed archives fuzz/seeds/<target>_seed_corpus.zip (OSS-Fuzz's name for a target's seeds).

An archive holds a flat set of inputs, each named by the SHA-1 of its bytes (as libFuzzer names
corpus files). Written deterministically: entries in name order, a fixed timestamp and fixed
permissions, deflated at level 9, so one set of inputs always gives the same bytes and a
re-export that found nothing new leaves no diff.
"""
import hashlib
import pathlib
import zipfile

# The earliest time a zip entry can hold: no clock or time zone leaks into the archive.
FIXED_TIME = (1980, 1, 1, 0, 0, 0)
UNIX = 3  # "made by" system: permissions below are read as Unix modes
MODE = 0o100644  # regular file, rw-r--r--


class SeedError(Exception):
    """A seed archive that cannot be read or written as one."""


def entry_name(data):
    return hashlib.sha1(data).hexdigest()


def read_seeds(archive):
    """{name: bytes} of archive's inputs. Raises SeedError for an unreadable archive or an entry
    that is not a plain file name (a directory, a path, a name that is not its bytes' SHA-1)."""
    archive = pathlib.Path(archive)
    try:
        with zipfile.ZipFile(archive) as z:
            out = {}
            for info in z.infolist():
                name = info.filename
                if info.is_dir() or "/" in name or "\\" in name or name in ("", ".", ".."):
                    raise SeedError(f"{archive}: entry '{name}' is not a plain input file")
                data = z.read(info)
                if name != entry_name(data):
                    raise SeedError(f"{archive}: entry '{name}' is not named by the SHA-1 of its bytes "
                                    f"({entry_name(data)})")
                out[name] = data
            return out
    except (OSError, zipfile.BadZipFile) as e:
        raise SeedError(f"{archive}: cannot read the seed archive ({e})") from e


def unpack_seeds(archive, directory):
    """Writes archive's inputs into directory (made if missing); returns how many."""
    seeds = read_seeds(archive)
    directory = pathlib.Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    for name, data in seeds.items():
        (directory / name).write_bytes(data)
    return len(seeds)


def write_seeds(archive, inputs):
    """Writes the set of byte strings `inputs` as archive, replacing it only once complete."""
    archive = pathlib.Path(archive)
    archive.parent.mkdir(parents=True, exist_ok=True)
    named = {entry_name(data): data for data in inputs}
    tmp = archive.with_name(archive.name + ".tmp")
    try:
        with zipfile.ZipFile(tmp, "w") as z:
            for name in sorted(named):
                info = zipfile.ZipInfo(name, date_time=FIXED_TIME)
                info.create_system = UNIX
                info.external_attr = MODE << 16
                info.compress_type = zipfile.ZIP_DEFLATED
                z.writestr(info, named[name], compresslevel=9)
        tmp.replace(archive)
    except OSError as e:
        tmp.unlink(missing_ok=True)
        raise SeedError(f"{archive}: cannot write the seed archive ({e})") from e
