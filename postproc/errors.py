"""The one exception type for bad input to the analysis."""


class InputError(ValueError):
    """Bad input (missing file, NaN, unknown ids, no contacts, zero volume,
    wrong options...). The message is one line that names the problem and
    where it is; the CLI prints it as is and exits non-zero."""
