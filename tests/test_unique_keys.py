"""unique_inverse gives numpy's unique and inverse exactly, on grid keys and at the fallbacks."""

import numpy as np
import pytest

from realsim.perception.unique_keys import distinct_rows, first_rows, unique_inverse


@pytest.mark.parametrize(("n", "low", "high", "dtype"), [
    (200_000, -(10**9), 10**9, np.int64),  # packed path
    (5_000, 0, 40, np.int32),  # many repeats, narrow type
    (1, 3, 4, np.int64),
    (3_000, -(2**62), 2**62, np.int64),  # range too wide to pack: numpy's own path
    (500, 0, 255, np.uint8),
])
def test_matches_numpy(n: int, low: int, high: int, dtype: type) -> None:
    keys = np.random.default_rng(n).integers(low, high, n, dtype=dtype)
    uniq, inverse = unique_inverse(keys)
    ref_uniq, ref_inverse = np.unique(keys, return_inverse=True)
    assert uniq.dtype == ref_uniq.dtype
    np.testing.assert_array_equal(uniq, ref_uniq)
    np.testing.assert_array_equal(inverse, ref_inverse.ravel())
    np.testing.assert_array_equal(uniq[inverse], keys)


def test_empty_and_float() -> None:
    uniq, inverse = unique_inverse(np.zeros(0, np.int64))
    assert len(uniq) == 0 and len(inverse) == 0
    uniq, inverse = unique_inverse(np.array([0.5, -1.0, 0.5]))
    np.testing.assert_array_equal(uniq, [-1.0, 0.5])
    np.testing.assert_array_equal(inverse, [1, 0, 1])


@pytest.mark.parametrize("spread", [5, 10**6, 2**40])
def test_distinct_rows(spread: int) -> None:
    rng = np.random.default_rng(spread)
    cells = rng.integers(-spread, spread, (20_000, 3), dtype=np.int64)
    cells[::3] = cells[1::3][: len(cells[::3])]  # repeated rows
    assert distinct_rows(cells) == len(np.unique(cells, axis=0))
    assert distinct_rows(cells[:0]) == 0


@pytest.mark.parametrize("spread", [5, 10**6, 2**40])
def test_first_rows(spread: int) -> None:
    rng = np.random.default_rng(spread)
    cells = rng.integers(-spread, spread, (20_000, 3), dtype=np.int64)
    cells[::3] = cells[1::3][: len(cells[::3])]  # repeated rows: the first of each is kept
    np.testing.assert_array_equal(first_rows(cells), np.sort(np.unique(cells, axis=0, return_index=True)[1]))
    assert len(first_rows(cells[:0])) == 0
