"""The exceptions the radiosity package raises, one for each way the program can fail.

The program (``radiosity`` on the command line) ends with exit status 2 for bad input and 1 for
a runtime or device failure; the package raises the matching exception instead, with the same
one-line message (naming the file and the problem):

- :class:`InputError` (exit status 2): an option's value, a properties file, a scene that cannot
  be solved. Also a :class:`ValueError`.
- :class:`FileError` (exit status 2): a file that cannot be read or is malformed; a subclass of
  :class:`InputError` with ``path`` (the file) and ``problem`` (what is wrong with it).
- :class:`RuntimeFailure` (exit status 1): the OpenCL device failed, memory ran out, an output
  could not be written. Also a :class:`RuntimeError`.

All three derive from :class:`RadiosityError`.
"""


class RadiosityError(Exception):
    """Base of every error the radiosity package raises on purpose."""


class InputError(RadiosityError, ValueError):
    """Bad input: an option's value, a properties file, a scene that cannot be solved (exit status 2)."""


class FileError(InputError):
    """A file that cannot be read or is malformed; ``path`` names it, ``problem`` says what is wrong."""

    path = None
    problem = None


class RuntimeFailure(RadiosityError, RuntimeError):
    """The machine failed: an OpenCL device error, memory, an output that could not be written (exit status 1)."""


class RadiosityWarning(UserWarning):
    """A warning the program prints on standard error (``radiosity: warning: ...``): a result to read with care."""
