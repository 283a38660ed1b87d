"""Where the blocks of a stack are: outlines and contact points at a state of motion.

Pure geometry for drawing a time history (:mod:`freestand.core.dynamics.timehistory`).

A rigid placement ("pose") maps a point ``X`` of a block at rest to its place
``x = R(theta) X + d`` in the support's frame, ``R`` the counter-clockwise
rotation. A block with the state ``q = (u_x, u_z, phi)`` of
:func:`freestand.core.dynamics.timehistory.simulate` (its centre ``C`` displaced by
``u``, rotated by ``phi`` about it) has ``theta = phi`` and
``d = C + u - R(phi) C``, i.e. ``x = C + u + R(phi) (X - C)``.

The model gives a block's centre of gravity and lower contacts, not its
shape: :func:`block_outlines` draws a schematic rectangle over the contacts.
"""

from __future__ import annotations

import math

import numpy as np

from freestand.core.model import Stack


def block_outlines(stack: Stack) -> tuple[np.ndarray, ...]:
    """Schematic outline of every block at rest: a rectangle over its lower contacts.

    Parameters
    ----------
    stack : Stack
        Blocks bottom to top.

    Returns
    -------
    tuple of numpy.ndarray
        One (4, 2) array per block: the corners (x [m], z [m]) counter-clockwise
        from the lower left contact. The bottom edge joins the lower contacts
        (``base_left`` to ``base_right`` at ``base_level``); the top is the
        level of the contacts of the block above, or, for the top block,
        ``base_level + 2 (z_S - base_level)`` (a homogeneous block's height).

    Notes
    -----
    The model file does not describe shapes; the rectangle only shows where
    the block stands and how it moves. The centre of gravity and the contacts
    are the model's.
    """
    outlines = []
    blocks = stack.blocks
    for index, block in enumerate(blocks):
        bottom = block.base_level
        if index + 1 < len(blocks) and blocks[index + 1].base_level > bottom:
            top = blocks[index + 1].base_level
        else:
            top = bottom + 2.0 * max(block.centre[1] - bottom, 0.0)
        if not top > bottom:
            top = bottom + 0.1 * (block.base_right - block.base_left)
        outlines.append(
            np.array(
                [
                    [block.base_left, bottom],
                    [block.base_right, bottom],
                    [block.base_right, top],
                    [block.base_left, top],
                ]
            )
        )
    return tuple(outlines)


def _rotation(angle: float) -> np.ndarray:
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, -s], [s, c]])


def place(pose: np.ndarray, points: np.ndarray) -> np.ndarray:
    """Move points of a block at rest to their place: ``x = R(theta) X + d``.

    Parameters
    ----------
    pose : numpy.ndarray
        ``(theta [rad], d_x [m], d_z [m])``.
    points : numpy.ndarray
        Shape (..., 2): points ``X`` (x, z) [m] of the block at rest.

    Returns
    -------
    numpy.ndarray
        Same shape: the points in the support's frame [m].
    """
    points = np.asarray(points, dtype=float)
    return points @ _rotation(pose[0]).T + np.asarray(pose[1:3], dtype=float)


def _compose(outer: np.ndarray, inner: np.ndarray) -> np.ndarray:
    """Pose of ``outer`` after ``inner``: ``x = R_o (R_i X + d_i) + d_o``."""
    return np.array([outer[0] + inner[0], *(_rotation(outer[0]) @ inner[1:3] + outer[1:3])])


def _inverse(pose: np.ndarray) -> np.ndarray:
    return np.array([-pose[0], *(-(_rotation(-pose[0]) @ pose[1:3]))])


def stack_poses(stack: Stack, position: np.ndarray, exaggeration: float = 1.0) -> np.ndarray:
    """Pose of every block at a state, with rotations relative to the body below scaled.

    Parameters
    ----------
    stack : Stack
        Blocks bottom to top.
    position : numpy.ndarray
        Shape (B, 3): ``(u_x [m], u_z [m], phi [rad])`` of each block, as in
        :class:`freestand.core.dynamics.timehistory.TimeHistoryResult` (NaN after a
        block overturned).
    exaggeration : float, optional
        Factor ``k`` [-] on each block's rotation relative to the body below,
        positive; 1 (default) gives the true poses. Exaggerated rotations are
        limited to +-pi/2.

    Returns
    -------
    numpy.ndarray
        Shape (B, 3): ``(theta [rad], d_x [m], d_z [m])`` of each block (NaN
        where the state is NaN, and for the blocks on it).

    Notes
    -----
    Let ``A_i`` be the true pose of block ``i`` and ``T_i = A_{i-1}^-1 A_i``
    its pose relative to the body below (``A_-1`` the support, identity),
    with relative rotation ``theta_i``. Its pivot ``P`` is the lower contact
    that is lowest above the surface of the body below (smallest gap,
    ``(T_i P)_z - base_level``). The drawn relative pose keeps where the
    pivot is and turns the block by ``k theta_i`` about it,
    ``T'_i X = T_i P + R(k theta_i) (X - P)``, and the drawn poses are
    ``D_i = D_{i-1} T'_i``. Slides and the pivot's lift stay true; the
    other contact's lift grows with the rotation. The drawn relative rotation
    ``k theta_i`` is limited to +-pi/2 (a block lying on its side). For
    ``k = 1``, ``D_i = A_i`` (no limit).
    """
    if not exaggeration > 0.0:
        raise ValueError(f"exaggeration must be positive, not {exaggeration!r}")
    blocks = stack.blocks
    q = np.asarray(position, dtype=float).reshape(len(blocks), 3)
    poses = np.full((len(blocks), 3), np.nan)
    actual_below = np.zeros(3)
    drawn_below = np.zeros(3)
    for i, block in enumerate(blocks):
        if not np.all(np.isfinite(q[i])) or not np.all(np.isfinite(drawn_below)):
            break
        centre = np.array(block.centre, dtype=float)
        actual = np.array([q[i, 2], *(centre + q[i, :2] - _rotation(q[i, 2]) @ centre)])
        if exaggeration == 1.0:
            drawn = actual
        else:
            relative = _compose(_inverse(actual_below), actual)
            contacts = np.array(block.contacts, dtype=float)
            lift = place(relative, contacts)[:, 1] - block.base_level
            pivot = contacts[int(np.argmin(lift))]
            turned = min(max(exaggeration * relative[0], -0.5 * math.pi), 0.5 * math.pi)
            moved = place(relative, pivot) - _rotation(turned) @ pivot
            drawn = _compose(drawn_below, np.array([turned, *moved]))
        poses[i] = drawn
        actual_below, drawn_below = actual, drawn
    return poses
