"""The one exception type for bad input to the analysis."""


class InputError(ValueError):
    """Bad input (missing file, NaN, unknown ids, no contacts, zero volume,
    wrong options...). The message is one line that names the problem and
    where it is; the CLI prints it as is and exits non-zero."""


def read_json(path, what="JSON file"):
    """The JSON value in the file ``path``, read as UTF-8 whatever the
    locale.

    Parameters
    ----------
    path : str
        The file.
    what : str
        What the file should be, for the message ("study manifest", "run
        info file"...).

    Raises
    ------
    InputError
        One line naming the file when it is missing or unreadable, is not
        UTF-8 text, or is not JSON (with the line and column of the fault).

    Examples
    --------
    >>> import tempfile, os
    >>> d = tempfile.mkdtemp()
    >>> p = os.path.join(d, "m.json")
    >>> _ = open(p, "w").write('{"runs": [')
    >>> try:
    ...     read_json(p, "manifest")
    ... except InputError as e:
    ...     print(str(e).replace(d, "D"))
    D/m.json: not valid JSON (Expecting value at line 1, column 11), so not a manifest
    """
    import json

    try:
        with open(path, encoding="utf-8") as fh:
            return json.load(fh)
    except FileNotFoundError:
        raise InputError(f"{path}: no such file") from None
    except OSError as exc:
        raise InputError(f"{path}: cannot read the {what}: {exc.strerror or exc}") from None
    except UnicodeDecodeError as exc:
        raise InputError(f"{path}: not UTF-8 text (byte {exc.start}), so not a {what}") from None
    except json.JSONDecodeError as exc:
        raise InputError(f"{path}: not valid JSON ({exc.msg} at line {exc.lineno}, column {exc.colno}), "
                         f"so not a {what}") from None
    except RecursionError:
        raise InputError(f"{path}: JSON nested too deeply to read, so not a {what}") from None


def read_json_object(path, what="JSON file"):
    """:func:`read_json` for a file that must hold a JSON object (a dict);
    InputError naming the file when it holds anything else."""
    value = read_json(path, what)
    if not isinstance(value, dict):
        raise InputError(f"{path}: not a {what} (a JSON {type(value).__name__}, not an object)")
    return value
