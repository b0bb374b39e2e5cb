"""What the Python tests share: each failed check said as it is found and kept for the end.

    from checks import check, failures
    check(x == 2, f"x is {x}, not 2")
    ...
    return 1 if failures else 0
"""

# Every failed check's message, in order; a test's exit status is 1 when it is not empty.
failures = []


def check(ok, message):
    """Records `message` as a failure, and prints it, when `ok` is false; returns `ok`."""
    if not ok:
        failures.append(message)
        print("FAIL:", message)
    return ok
