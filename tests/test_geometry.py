"""Outlines and drawn poses of the blocks (freestand.core.geometry)."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from freestand.core.dynamics.timehistory import stack_kinematics
from freestand.core.geometry import block_outlines, place, stack_poses
from freestand.core.model import Block, Friction, Stack


def rectangle(name, half_width, height, level, mass=100.0):
    return Block(
        name=name,
        mass=mass,
        inertia=mass * (4 * half_width**2 + height**2) / 12.0,
        centre=(0.1 * half_width, level + 0.5 * height),
        base_left=-half_width,
        base_right=half_width,
        base_level=level,
        friction=Friction(0.5, 0.4),
    )


TWO = Stack("two", (rectangle("lower", 1.0, 0.5, 0.0), rectangle("upper", 0.3, 1.5, 0.5)))


def rotation(angle):
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, -s], [s, c]])


def test_outlines_stand_on_the_contacts_and_reach_the_block_above(crane_model):
    stack = crane_model.configuration("x-z cart right")
    bridge, cart = block_outlines(stack)
    np.testing.assert_allclose(bridge, [[-5.9, 0.0], [3.9, 0.0], [3.9, 1.2], [-5.9, 1.2]])
    # the top block: twice its centre's height above its contacts (4.03 - 1.2 = 2.83)
    np.testing.assert_allclose(cart[:, 1], [1.2, 1.2, 1.2 + 5.66, 1.2 + 5.66])
    np.testing.assert_allclose(cart[:2, 0], [-0.76, 1.90])


def test_true_poses_put_the_contacts_where_the_kinematics_do():
    position = np.array([[0.01, 0.002, 0.03], [-0.05, 0.01, -0.2]])
    poses = stack_poses(TWO, position)
    kin = stack_kinematics(TWO, position, np.zeros_like(position))
    for i, block in enumerate(TWO.blocks):
        centre = np.array(block.centre)
        contacts = np.array(block.contacts)
        expected = centre + position[i, :2] + (contacts - centre) @ rotation(position[i, 2]).T
        np.testing.assert_allclose(place(poses[i], contacts), expected, atol=1e-14)
        np.testing.assert_allclose(place(poses[i], centre), centre + position[i, :2], atol=1e-14)
    # the gaps of the kinematics, seen on the drawn blocks: upper contacts against the
    # lower block's top line (rotated with it)
    lower_top = place(poses[0], np.array([[0.0, 0.5], [1.0, 0.5]]))
    normal = rotation(poses[0, 0]) @ np.array([0.0, 1.0])
    upper_contacts = place(poses[1], np.array(TWO.blocks[1].contacts))
    np.testing.assert_allclose((upper_contacts - lower_top[0]) @ normal, kin.gap[1], atol=1e-14)


@settings(max_examples=40, deadline=None)
@given(
    angle=st.floats(-0.5, 0.5).filter(lambda a: abs(a) > 1e-6),
    slide=st.floats(-0.2, 0.2),
    factor=st.floats(1.5, 1000.0),
)
def test_exaggeration_turns_about_the_pivot_and_keeps_the_slide(angle, slide, factor):
    """A block rocking on one corner (shifted by a slide): drawn turned k times about it."""
    block = rectangle("one", 0.3, 1.2, 0.0)
    stack = Stack("one", (block,))
    pivot = np.array(block.contacts[0 if angle > 0 else 1])  # +angle lifts the right corner
    centre = np.array(block.centre)
    moved_centre = pivot + rotation(angle) @ (centre - pivot) + np.array([slide, 0.0])
    position = np.array([[*(moved_centre - centre), angle]])
    drawn = stack_poses(stack, position, exaggeration=factor)[0]
    expected = min(max(factor * angle, -math.pi / 2), math.pi / 2)  # drawn at most on its side
    assert drawn[0] == pytest.approx(expected)
    np.testing.assert_allclose(place(drawn, pivot), pivot + [slide, 0.0], atol=1e-12)
    # the other corner lifts: drawn higher than the pivot
    other = np.array(block.contacts[1 if angle > 0 else 0])
    assert place(drawn, other)[1] > 0.0


def test_exaggeration_keeps_the_upper_block_on_the_drawn_lower_one():
    # lower block rocks on its left corner; upper rocks on its right corner relative to it
    position = np.zeros((2, 3))
    poses_true = np.zeros((2, 3))
    lower, upper = TWO.blocks
    for i, (block, angle, corner) in enumerate(((lower, 0.002, 0), (upper, -0.01, 1))):
        pivot = np.array(block.contacts[corner])
        centre = np.array(block.centre)
        relative_centre = pivot + rotation(angle) @ (centre - pivot)
        if i == 0:
            position[0] = [*(relative_centre - centre), angle]
        else:
            # place the upper block's relative pose on the true lower pose
            theta0, d0 = poses_true[0, 0], poses_true[0, 1:]
            world_centre = rotation(theta0) @ relative_centre + d0
            position[1] = [*(world_centre - centre), theta0 + angle]
        poses_true = stack_poses(TWO, position)
    drawn = stack_poses(TWO, position, exaggeration=100.0)
    assert drawn[0, 0] == pytest.approx(0.2)
    assert drawn[1, 0] - drawn[0, 0] == pytest.approx(-1.0)
    # the upper pivot (right corner) lies on the drawn lower block's top surface, at the
    # same place along it as in truth
    pivot_drawn = place(drawn[1], np.array(upper.contacts[1]))
    in_lower = rotation(-drawn[0, 0]) @ (pivot_drawn - drawn[0, 1:])
    np.testing.assert_allclose(in_lower, upper.contacts[1], atol=1e-12)


def test_a_nan_state_gives_nan_poses_above_it():
    position = np.array([[np.nan, np.nan, np.nan], [0.0, 0.0, 0.0]])
    poses = stack_poses(TWO, position)
    assert np.all(np.isnan(poses))
    poses = stack_poses(TWO, np.array([[0.0, 0.0, 0.0], [np.nan] * 3]), exaggeration=10.0)
    assert np.all(np.isfinite(poses[0])) and np.all(np.isnan(poses[1]))
    with pytest.raises(ValueError, match="exaggeration"):
        stack_poses(TWO, np.zeros((2, 3)), exaggeration=0.0)
