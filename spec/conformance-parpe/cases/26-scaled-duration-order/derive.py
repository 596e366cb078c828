#!/usr/bin/env python3
"""Derives expected.csv of this case from PARSL 1.0.1 section 7.1 and section 13 rule 22, in IEEE
doubles (Python floats round + - * / exactly as Java doubles do). Run from this folder."""
T0, SUM, period, dt, g = 3.0, 10.0, 1.0, 0.1, 1e12
D = (T0 * period) / SUM          # rule 22: (T * period) / SumT, in that order; = the double nearest 0.3
p = [0.0]                        # placement at u = 0: state s, p = p0 = 0, a0 = 0
for k in range(2):
    p.append(p[-1] + dt / D)     # section 7.1 step 2: the state goes on, p += r / D
rows = ['time,m0']
for k, pk in enumerate(p):
    q = (pk - 0.0) / (1 - 0.0)   # q = (p - p0) / (1 - p0)
    angle = 0.0 + (g - 0.0) * q  # a0 + (g - a0) * q, linear profile
    rows.append('%.6f,%.6f' % (k * dt, angle))  # Python's '%.6f' rounds the exact value half-even, like C
with open('expected.csv', 'w') as f:
    f.write('\n'.join(rows) + '\n')
