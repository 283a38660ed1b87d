"""Names of the paper's section 3 cases for two-block results.

The paper analyses two stacked blocks case by case (sections 3.1.1-3.1.2.3
and, by analogy, 3.2). The general solver finds the same states without that
case analysis; this module only names a two-block result in the paper's terms
so that an engineer can follow the paper. Other stacks have no paper case.
"""

from __future__ import annotations

from collections.abc import Sequence


def paper_case(stack, blocks: Sequence) -> str | None:
    """The paper's case for a two-block state, e.g. ``"3.1.2.3: bridge slides, cart rests on it"``.

    Parameters
    ----------
    stack : freestand.core.model.Stack
        The stack (for the block names).
    blocks : sequence of BlockState
        The state of each block, bottom to top.

    Returns
    -------
    str or None
        None for stacks of other sizes and states the paper does not treat.
    """
    if len(blocks) != 2:
        return None
    lower, upper = blocks
    low, up = lower.motion.value, upper.motion.value
    lname, uname = lower.name, upper.name
    if low == "rest":
        if up == "rest":
            return f"3.1.1.1 and 3.1.2.1a: {uname} and {lname} at rest"
        if up == "rock":
            return f"3.1.1.2: {uname} rocks about its {upper.pivot} edge on the steady {lname}"
        if up == "slide":
            return f"3.2: {uname} slides on the steady {lname}"
        if up == "slide-rock":
            return f"3.2 (by analogy with 3.1.2.2d): {uname} rocks and slides on the steady {lname}"
        return None
    if up == "rest":
        if low == "slide":
            return f"3.1.2.3: {lname} slides, {uname} rests on it"
        if low == "rock":
            return f"3.1.2.2c: {lname} rocks about its {lower.pivot} edge, {uname} rests on it"
        if low == "slide-rock":
            return (
                f"3.1.2.2d: {lname} rocks about its {lower.pivot} edge and slides, "
                f"{uname} rests on it"
            )
        return None
    if low == "slide" and up == "rock":
        return (
            f"3.1.2.3 (C_z = 0): {lname} slides, {uname} rocks about its {upper.pivot} edge on it"
        )
    return None
