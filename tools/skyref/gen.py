#!/usr/bin/env python3
"""Reference sun and moon positions for the engine's ephemeris test (engine/src/sky).

Writes ephemeris.csv beside this script: one row per (place, UTC instant) with
  sun:  geometric elevation and azimuth from pvlib's NREL SPA (method 'nrel_numpy',
        column 'elevation' = no refraction), azimuth from north towards east;
  moon: topocentric elevation and azimuth from PyEphem with pressure 0 (no refraction),
        phase angle (Sun-Moon-Earth) from the elongation and the two distances,
        illuminated fraction from PyEphem (moon_phase).
Run once, offline (never at build or test time):
  python3 -m venv /tmp/skyvenv && /tmp/skyvenv/bin/pip install pvlib ephem
  /tmp/skyvenv/bin/python tools/skyref/gen.py
Versions used for the committed CSV are written into its header.
"""
import csv
import math
import os
import random

import ephem
import pandas as pd
import pvlib

HERE = os.path.dirname(os.path.abspath(__file__))


def cases():
    rng = random.Random(34)
    places = [(51.4779, -0.0015), (-33.8688, 151.2093), (64.1466, -21.9426),
              (0.0, 0.0), (35.6762, 139.6503), (-54.8, -68.3), (78.22, 15.65),
              (19.43, -99.13)]
    out = []
    for i in range(48):
        lat, lon = places[i % len(places)]
        year = rng.randint(1950, 2080)
        month = rng.randint(1, 12)
        day = rng.randint(1, 28)
        hour, minute, second = rng.randint(0, 23), rng.randint(0, 59), rng.randint(0, 59)
        out.append((lat, lon, year, month, day, hour, minute, second))
    return out


def main():
    rows = []
    for lat, lon, y, mo, d, h, mi, s in cases():
        t = pd.DatetimeIndex([pd.Timestamp(y, mo, d, h, mi, s, tz="UTC")])
        sp = pvlib.solarposition.get_solarposition(t, lat, lon, altitude=0,
                                                   method="nrel_numpy")
        obs = ephem.Observer()
        obs.lat, obs.lon = str(lat), str(lon)
        obs.elevation = 0
        obs.pressure = 0
        obs.date = f"{y}/{mo}/{d} {h}:{mi}:{s}"
        moon = ephem.Moon(obs)
        sun = ephem.Sun(obs)
        psi = abs(float(moon.elong))
        r_sun, r_moon = sun.earth_distance, moon.earth_distance
        phase = math.atan2(r_sun * math.sin(psi), r_moon - r_sun * math.cos(psi))
        rows.append([lat, lon, y, mo, d, h, mi, s,
                     f"{sp['elevation'].iloc[0]:.6f}", f"{sp['azimuth'].iloc[0]:.6f}",
                     f"{math.degrees(moon.alt):.6f}", f"{math.degrees(moon.az):.6f}",
                     f"{math.degrees(phase):.5f}", f"{moon.moon_phase:.6f}"])
    path = os.path.join(HERE, "ephemeris.csv")
    with open(path, "w", newline="") as f:
        f.write(f"# tools/skyref/gen.py: pvlib {pvlib.__version__} (nrel_numpy), "
                f"ephem {ephem.__version__}; degrees, UTC, azimuth from north towards east\n")
        w = csv.writer(f)
        w.writerow(["lat", "lon", "year", "month", "day", "hour", "minute", "second",
                    "sun_elev", "sun_az", "moon_elev", "moon_az", "moon_phase_angle",
                    "moon_illuminated"])
        w.writerows(rows)
    print(f"wrote {len(rows)} rows to {path}")


if __name__ == "__main__":
    main()
