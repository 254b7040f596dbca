"""The plain-text progress bar and its time estimate."""
import io

from viscocontact.studies.progress import Progress


class Clock:
    """A clock set by hand: the tests check the text of the estimate, nothing is timed."""

    def __init__(self):
        self.t = 0.0

    def __call__(self):
        return self.t


def test_log_lines_with_estimate():
    stream, clock = io.StringIO(), Clock()
    bar = Progress("sweep", total=4, stream=stream, clock=clock)
    clock.t = 10.0
    bar.update(note="adhesive ζ=0.1 converged")
    clock.t = 20.0
    bar.update()
    bar.close("done")
    lines = stream.getvalue().splitlines()
    assert lines[0].startswith("sweep 1/4 [#####") and "25%" in lines[0]
    assert "0:10 elapsed" in lines[0] and "~0:30 left" in lines[0]
    assert lines[0].endswith("converged")
    assert "2/4" in lines[1] and "~0:20 left" in lines[1]
    assert lines[2] == "done"


def test_resumed_points_do_not_count_in_the_rate_and_total_may_change():
    stream, clock = io.StringIO(), Clock()
    bar = Progress("cycle", total=10, done=5, stream=stream, clock=clock)
    assert "? left" in bar.line()
    clock.t = 3.0
    bar.update(total=8)
    assert "6/8" in stream.getvalue() and "~0:06 left" in stream.getvalue()


def test_terminal_redraws_in_place_and_silence():
    class Tty(io.StringIO):
        def isatty(self):
            return True

    stream = Tty()
    bar = Progress("sweep", total=2, stream=stream)
    bar.update()
    bar.update()
    bar.close()
    text = stream.getvalue()
    assert text.count("\r") == 2 and text.endswith("\n") and text.count("\n") == 1
    Progress("sweep", total=2, stream=None).update()   # no output, no error
