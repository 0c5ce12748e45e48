"""What the bench scripts share: rtrace's RGB as luminance (Radiance's
weights, as bench/score.py), and numeric rows of a text file."""


def luminance(rgb):
    return 0.265 * rgb[0] + 0.670 * rgb[1] + 0.065 * rgb[2]


def rows(text):
    """Numbers of each non-blank line that is not a comment."""
    return [[float(x) for x in line.split()] for line in text.splitlines()
            if line.strip() and not line.startswith("#")]


def read_rows(path):
    with open(path) as f:
        return rows(f.read())
