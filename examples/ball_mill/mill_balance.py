#!/usr/bin/env python3
"""Per revolution of in.ball_mill: the mean torque of the charge on the drum,
the torque arm M g x_cm, the change of the charge's angular momentum about
the axis over the revolution, and the balance
<f_mill[5]> = <M g x_cm> - (L_end - L_start) / T_rev.

    /usr/bin/python3 mill_balance.py [log.ball_mill] [mill_rev.txt] [rpm]
Prints one row per revolution; mill_balance() returns them for the plot and
the short test."""
import sys


def mill_balance(log="log.ball_mill", rev="mill_rev.txt", rpm=100.0):
    L, hdr, on = {}, None, False
    for line in open(log):
        w = line.split()
        if w and w[0] == "Step":
            hdr, on = w, True
            continue
        if on:
            if not w or not w[0].isdigit():
                on = False
                continue
            r = dict(zip(hdr, w))
            L[int(r["Step"])] = float(r["c_L"])
    out, prev = [], 0
    for line in open(rev):
        if line.startswith("#"):
            continue
        w = line.split()
        step, torque, arm, power = int(w[0]), float(w[1]), float(w[2]), float(w[3])
        dl = (L[step] - L[prev]) / (60.0 / rpm)
        out.append((torque, arm, dl, power))
        prev = step
    return out


if __name__ == "__main__":
    rows = mill_balance(*sys.argv[1:3], *(float(x) for x in sys.argv[3:4]))
    print("rev  torque [mN m]  M g x_cm [mN m]  dL/T [mN m]  balance (rel.)  power [mW]")
    for k, (t, a, d, p) in enumerate(rows, 1):
        print(f"{k:3d}  {1e3 * t:13.4f}  {1e3 * a:15.4f}  {1e3 * d:11.4f}  {(t - (a - d)) / t:14.2e}  {1e3 * p:10.2f}")
