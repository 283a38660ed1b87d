"""The 3-D engine's integer state: event kinds, the counters of ``istate`` and the statuses.

Shared by the loop (:mod:`freestand.core.dynamics.body_engine`), the remedy
(:mod:`freestand.core.dynamics.body_remedy`) and the front end
(:mod:`freestand.core.dynamics.body_history`).
"""

from __future__ import annotations

# event kinds
EV_START = 0
EV_IMPACT = 1
EV_LIFT_OFF = 2
EV_SLIP = 3
EV_STICK = 4
EV_OVERTURN = 5
EV_REMEDY = 6
EV_LANDING_MISS = 7
EVENT_KINDS = ("start", "impact", "lift-off", "slip", "stick", "overturn", "remedy", "pass-over")

# istate
I_RECORDS = 0
I_EVENTS = 1
I_STATUS = 2
I_STEPS = 3
I_REMEDIES = 4
I_IMPACTS = 5
I_STRETCH = 6  # while a stretch of time stepping runs (the remedy): its steps so far + 1; else 0
I_STRETCH_STEPS = 7
I_CHATTER = 8  # 1 while the stretch is a chatter's: it ends on a stick or a slip of speed
I_TRIALS = 9  # RK4 trials of the event searches (locate)
I_SIZE = 10

STATUS_RUNNING = 0
STATUS_COMPLETED = 1
STATUS_OVERTURNED = 2
STATUS_BUFFER_FULL = 3
