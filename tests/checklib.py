"""What the check_*.py tests share: every failed check printed as it happens and tallied, and
the exit status from the tally."""
import sys

failures = []


def check(ok, what):
    """Records what when ok is false; returns ok."""
    if not ok:
        failures.append(what)
        print("FAIL:", what)
    return ok


def done(name):
    """Prints the tally and exits: 0 when every check held."""
    print("%s: %d problems" % (name, len(failures)))
    sys.exit(1 if failures else 0)
