"""How broadly the checker reads what students type (issue #31, item 3): the same correct
relations typed in many notations, and a few wrong ones so that marking everything correct fails.

Each case is a one- or few-line derivation fed to ``derive.check(..., derivation=...)``. A correct
case passes when every line is judged correct (none wrong, none "not read", none carried); a wrong
case passes when some line is judged wrong.

Values worked by hand from each problem's givens (never from derive's output):

- byjus-4kg-ball-catches-8kg-ball (direct): m_A = 4, m_B = 8, e = 0.5, v_A1 = 12, v_B1 = 4 (m/s).
  Momentum 4(12) + 8(4) = 80 = 4 v_A2 + 8 v_B2; restitution v_B2 - v_A2 = 0.5(12 - 4) = 4;
  so 12 v_A2 = 48, v_A2 = 4, v_B2 = 8. KE before ½·4·144 + ½·8·16 = 288 + 64 = 352 J, after
  ½·4·16 + ½·8·64 = 32 + 256 = 288 J, lost 64 J. Common velocity 80/12 = 6.667. Impulse on B
  8(8 - 4) = 32 N s.
- edexcel-m2-ball-rebounds-from-wall (wall): m_A = 2, e = 0.4, v_A1 = 4 toward the wall (+).
  v_A2 = -0.4(4) = -1.6; KE lost ½·2·16 - ½·2·2.56 = 16 - 2.56 = 13.44 J; impulse 2(1.6 + 4) = 11.2 N s.
- notes-4c11-two-spheres (oblique): cos 37.6° = 0.79229, sin 37.6° = 0.61015. v_A1n = 3.9614,
  v_A1t = 3.0507, v_B1n = -11.884, v_B1t = -9.1522. n-momentum 20(3.9614) + 5(-11.884) = 19.807;
  restitution v_B2n - v_A2n = 0.6(15.846) = 9.5075; 25 v_A2n = 19.807 - 47.537 = -27.730,
  v_A2n = -1.1092, v_B2n = 8.3983; speed of A after sqrt(1.1092² + 3.0507²) = 3.2461.
- aqa-m3-2014-symbolic-2m-hits-m (symbolic): m_A = 2m, m_B = m, e = 2/3, v_A1 = 2u, v_B1 = 0.
  4u = 2 v_A2 + v_B2, v_B2 - v_A2 = 4u/3; 3 v_A2 = 8u/3, v_A2 = 8u/9, v_B2 = 20u/9.
  KE before ½(2m)(4u²) = 4mu², after m(64/81)u² + ½m(400/81)u² = 264mu²/81, lost 20mu²/27.
- mcasco-two-cars-no-bounce (plastic, weights in lb): 4500 lb at 3 ft/s, 3000 lb at 6 ft/s the
  other way; g cancels: 4500(3) - 3000(6) = 13500 - 18000 = -4500 lb ft/s; the common velocity
  -4500/7500 = -0.6 ft/s. A number typed with its thousands spaced (``4 500``) or
  set off by commas (``4,500``) is one number.

Names in brackets with their marks after them, as Hibbeler and Beer & Johnston write them
(``(v_A)_1``, ``(v_A)_2``, ``(v_A)'``, ``(v_B)_n'``, ASCII ``(vA)1`` with ``mA``): the same
relations as above, the brackets only holding the name together. Column vectors (``pmatrix``,
``bmatrix``, ``array``, ``\\binom``) are the line of centres' component over the other's.
"""

from __future__ import annotations

import functools

import pytest

import derive

DIRECT = "byjus-4kg-ball-catches-8kg-ball"
WALL = "edexcel-m2-ball-rebounds-from-wall"
OBLIQUE = "notes-4c11-two-spheres"
SYMBOLIC = "aqa-m3-2014-symbolic-2m-hits-m"
CARS = "mcasco-two-cars-no-bounce"

CORRECT: dict[str, list[str]] = {
    DIRECT: [
        "4*12 + 8*4 = 4*v_A2 + 8*v_B2",
        "4(12) + 8(4) = 4v_A2 + 8v_B2",
        "(4)(12) + (8)(4) = 80",
        "4 × 12 + 8 × 4 = 4 v_A2 + 8 v_B2",
        "4·12 + 8·4 = 80 kg m/s",
        r"$4 \cdot 12 + 8 \cdot 4 = 4v_{A2} + 8v_{B2}$",
        r"$$4\times 12 + 8\times 4 = 4\,v_{A2} + 8\,v_{B2}$$",
        r"\( m_A v_{A1} + m_B v_{B1} = m_A v_{A2} + m_B v_{B2} \)",
        "v_B2 - v_A2 = 0.5(12 - 4)",
        "v_B2 - v_A2 = .5(12 - 4) = 4",
        "v_B2 − v_A2 = ½(12 − 4) = 4",
        "v_B2 - v_A2 = 1/2 (12 - 4)",
        "v_B2 - v_A2 = 0.5 * (12 - 4) = 4 m/s",
        r"$v_{B2} - v_{A2} = \frac{1}{2}(12 - 4) = 4$",
        r"$v_{B2} - v_{A2} = \dfrac12\left(12 - 4\right) = 4\ \mathrm{m/s}$",
        "e = (v_B2 - v_A2)/(v_A1 - v_B1)",
        r"$e = \frac{v_{B2} - v_{A2}}{v_{A1} - v_{B1}}$",
        "v_A2 = 4 m/s",
        "v_A2 = 4 ms^-1",
        "v_A2 = 4 m s⁻¹",
        "v_A2 = 4 m s^-1",
        r"$v_{A2} = 4\,\mathrm{m\,s^{-1}}$",
        r"$v_{A2} = 4 \text{ m s}^{-1}$",
        "v_B2 = 8.0 m/s",
        "v_B2 = 8.00 m/s",
        "v_B2 = 8 m/s (B speeds up)",
        "v_B2 = 8 m/s ✓",
        "v_A2 = 4 m/s, v_B2 = 8 m/s",
        "v_A2 = 4 m/s and v_B2 = 8 m/s",
        "12v_A2 = 48 → v_A2 = 4",
        "12 v_A2 = 48 ⇒ v_A2 = 4",
        "12v_A2 = 48 => v_A2 = 4",
        r"$12v_{A2} = 48 \Rightarrow v_{A2} = 4$",
        "4v_A2 + 8(v_A2 + 4) = 80",
        "v_A2 = (80 − 32)/12 = 4",
        "v_A2 = (80 - 8*4)/12",
        r"$v_{A2} = \frac{80 - 32}{12} = 4$ m/s",
        r"$$v_{B2} = v_{A2} + 4 = 8~\text{m/s}$$",
        "KE before = 0.5*4*12^2 + 0.5*8*4^2 = 352 J",
        "KE before = ½·4·12² + ½·8·4² = 352 J",
        "KE before = 3.52e2 J",
        "KE before = 3.52 × 10^2 J",
        "KE before = 3.52 x 10^2 J",
        r"$KE_{before} = 3.52 \times 10^{2}\,\mathrm{J}$",
        "KE lost = 352 - 288 = 64 J",
        "loss of KE = 64 J",
        "ΔKE = 352 − 288 = 64 J",
        r"$\Delta KE = \tfrac12(4)(12)^2 + \tfrac12(8)(4)^2 - 288 = 64\ \text{J}$",
        "v_G = (4*12 + 8*4)/(4 + 8) = 20/3",
        "v_G = 80/12 ≈ 6.67 m/s",
        "impulse on B = 8(8 - 4) = 32 N s",
        "impulse on B = 8 × (8 − 4) = 32 Ns",
        "3v_A2 = 12",
        "4(12) + 8(4) = 4v_A + 8v_B\nv_B - v_A = 0.5(12 - 4)\nv_A = 4, v_B = 8",
        "u_A = 12, u_B = 4\n4u_A + 8u_B = 4v_A + 8v_B\nv_A = 4 m/s, v_B = 8 m/s",
        "v_A2 = +4 m/s",
        "v_A2 = 4 m/s.",
        "v_A2 = 4 m/s (3 s.f.)",
        r"$v_{A2}=4\;\text{ms}^{-1}$",
        r"$v_{A2} = 4\,\text{m}\,\text{s}^{-1}$",
        r"$v_{A2} = 4\,\mathrm{m}\,\mathrm{s}^{-1}$",
        "v_{A2} = 4",
        "v_A2 = 48/12 = 4",
        "v_A2 = 48 ÷ 12 = 4",
        r"$v_{A2} = \frac{48}{12} = 4$",
        "**v_A2 = 4 m/s**",
        "- v_A2 = 4 m/s",
        "1. v_A2 = 4 m/s",
        "`v_A2 = 4`",
        r"$$\boxed{v_{A2} = 4\ \mathrm{m/s}}$$",
        r"$$\therefore v_{A2} = 4$$",
        "v_A2 = 4m/s",
        "v_B2 = 8 m/s   (2)",
        "0.5 = (v_B2 - v_A2)/(12 - 4)",
        "e(12 - 4) = v_B2 - v_A2",
        "(v_B2 - v_A2) = 0.5 × (12 - 4)",
        "v_B2 - v_A2 = 0.5(12-4)  ...(2)",
        r"$v_{B2} - v_{A2} = 0.5\left(12 - 4\right)$",
        r"$$v_{B2}-v_{A2}=\left(\frac{1}{2}\right)(12-4)$$",
        "4 × 12 + 8 × 4 = 80 kg m s⁻¹",
        "v_A2 = 4 m/s, so A keeps moving forward",
        "T_1 = 3.5 x 10^2 J",
        "KE after = 288 J",
        "v_A2 = 4 m/s   // A carries on",
        "v_A2 = 4 m/s   # A carries on",
        "v_A2 = 4 m/s & v_B2 = 8 m/s",
        "v_A2 ~ 4 m/s",
        "v_A2 ≃ 4 m/s",
        "4 x 12 + 8 x 4 = 4 x v_A2 + 8 x v_B2",
        "KE before = 0.5x4x12^2 + 0.5x8x4^2 = 352 J",  # x for times, typed without spaces
        "4x12 + 8x4 = 4x4 + 8x8",
        "KE after = 0.5x4.0x4.0^2 + 0.5x8.0x8.0^2 = 288 J",
        "KE lost = 352 J − 288 J = 64 J",
        "v_B2 - v_A2 = 0.5(12 m/s - 4 m/s) = 4 m/s",
        "KE lost = 6.4E1 J",
        "v_A2 = 4 m·s⁻¹",
        "v_A2 = 4 m/sec",
        r"$v_{A2} = \SI{4}{m/s}$",
        r"$v_{A2} = 4\ \frac{\mathrm{m}}{\mathrm{s}}$",
        "v_A2 = 4 (m/s)",
        "v_A2 = [80 − 32]/12 = 4",
        "CLM: 4(12) + 8(4) = 4v_A2 + 8v_B2 ... (1)",
        "NLR: (v_B2 - v_A2)/(12 - 4) = 0.5",
        r"$e=-\frac{v_{B2}-v_{A2}}{v_{B1}-v_{A1}}$",
        "v_B2 − v_A2 = −e(v_B1 − v_A1)",
        "∴ v_A2 = 4 m/s",
        "**Answer:** v_A2 = 4 m/s",
        "v'_A = 4 m/s",
        r"$v'_{A} = 4$",
        r"$v_{A}^{\prime} = 4$",
        "v_{A,2} = 4",
        "v_(A2) = 4",
        r"$v_{A,2} = 4$",
        "let x = v_A2, y = v_B2\n4x + 8y = 80\ny - x = 4\nx = 4, y = 8",
        "x = velocity of A after, y = velocity of B after\n48 + 32 = 4x + 8y\ny - x = 0.5(8) = 4\nso x = 4 and y = 8",
        "Let $x = v_{A2}$.\n$$4x + 8(x + 4) = 80 \\implies x = 4$$",
        # names in brackets with their marks after them (Hibbeler, Beer & Johnston)
        "4(12) + 8(4) = 4(v_A)_2 + 8(v_B)_2",
        "4(12) + 8(4) = 4 (v_A)' + 8 (v_B)'",
        "(v_B)_2 - (v_A)_2 = 0.5[(v_A)_1 - (v_B)_1]",
        "e = [(v_B)' - (v_A)'] / [(v_A) - (v_B)]",
        "mA(vA)1 + mB(vB)1 = mA(vA)2 + mB(vB)2",
        "4(12) + 8(4) = 4(vA)2 + 8(vB)2",
        "(vB)2 = (vA)2 + 4",
        "(+->)  mA(vA)1 + mB(vB)1 = mA(vA)2 + mB(vB)2",  # a sign convention's mark before it
        "(→+) 4(12) + 8(4) = 4(vA)2 + 8(vB)2",
        "+→: 4(12) + 8(4) = 80",
        "(vB)2 = 8 m/s ->",  # an arrow after the value: its direction
        "(vA)2 = 4 m/s (→)",
        "v_A2 = 4 m/s in the same direction as before",  # words after the value: what it is
        r"$4(12) + 8(4) = 4v_{A2} + 8v_{B2} \quad \cdots (1)$",
        r"$v_{A2}=4\,\mathrm{m}/\mathrm{s}$",
        "v<sub>B2</sub> − v<sub>A2</sub> = 0.5(12 − 4)",  # HTML's subscripts in Markdown
        "KE before = ½(4)(12<sup>2</sup>) + ½(8)(4<sup>2</sup>) = 352 J",
        r"$m_A(v_A)_1 + m_B(v_B)_1 = m_A(v_A)_{2} + m_B(v_B)_{2}$",
        r"$(v_B)^{\prime} - (v_A)^{\prime} = 0.5(12 - 4) = 4$",
        r"\[ 12(v_A)_2 = 48 \quad\Rightarrow\quad (v_A)_2 = 4\ \text{m/s} \]",
    ],
    WALL: [
        "v_A2 = -0.4(4) = -1.6 m/s",
        "v_A2 = −0.4 × 4 = −1.6 m s⁻¹",
        "v_A2 = -e v_A1 = -1.6",
        r"$v_{A2} = -e\,v_{A1} = -0.4 \cdot 4 = -1.6$",
        r"$v_{A2} = -0.4 \times 4 = -1.6\,\mathrm{m\,s^{-1}}$",
        "rebound speed = 0.4 × 4 = 1.6 m/s",
        "speed after = 1.6 ms^-1",
        "v_A2 = -8/5 m/s",
        "v_A2 = -1.60 m/s",
        "v_A2 = -1.6 m/s (away from the wall)",
        "KE lost = ½(2)(4²) − ½(2)(1.6²) = 16 − 2.56 = 13.44 J",
        "KE lost = 0.5*2*4^2 - 0.5*2*1.6^2 = 13.44 J",
        r"$\Delta E = \tfrac{1}{2}\cdot 2\cdot 4^2 - \tfrac12\cdot2\cdot1.6^2 = 13.44\,\mathrm{J}$",
        "loss of KE = 13.4 J",
        "KE before = 16 J, KE after = 2.56 J",
        r"$$KE_{lost} = 16 - 2.56 = 13.44 \text{ J}$$",
        "impulse = 2(1.6 + 4) = 11.2 N s",
        "e = rebound speed / approach speed",
        "v_A2 = -(0.4)(4) = -1.6",
        "KE lost = 1/2 × 2 × 4² − 1/2 × 2 × 1.6² = 13.44 J",
        r"$KE_{after} = \frac{1}{2}(2)(1.6)^2 = 2.56\,\mathrm{J}$",
        "v_A1 = 4 m/s towards the wall",
        "impulse = 2 × (1.6 − (−4)) = 11.2 Ns",
        "e = 1.6/4 = 0.4",
        r"$KE_{before} = \frac{1}{2}(2)(4)^2 = 16\ \mathrm{J}$",
        "impulse on the ball = 11.2 N s",
        "taking away from the wall as positive\nv_A1 = -4, v_A2 = 1.6",
    ],
    CARS: [
        "4 500(3) - 3 000(6) = 13 500 - 18 000 = -4 500",
        "V = -4 500/(7 500) = -0.6 ft/s",
        "4,500(3) - 3,000(6) = 13,500 - 18,000 = -4,500",
        "V = -4,500/7,500 = -0.600 ft/s",
        r"$V = \frac{-4\,500}{7\,500} = -0.6$ ft/s",
    ],
    SYMBOLIC: [
        "2m(2u) + m(0) = 2m v_A2 + m v_B2",
        "4mu = 2mv_A2 + mv_B2",
        "4u = 2v_A2 + v_B2",
        "v_B2 - v_A2 = (2/3)(2u) = 4u/3",
        "v_B2 − v_A2 = ⅔ · 2u",
        r"$v_{B2} - v_{A2} = \frac{2}{3}\left(2u\right) = \frac{4u}{3}$",
        r"$v_{B2} - v_{A2} = \frac23 \cdot 2u$",
        "3v_A2 = 4u - 4u/3 = 8u/3",
        "v_A2 = 8u/9",
        "v_A2 = (8/9)u",
        "v_A2 = 8/9 u",
        r"$v_{A2} = \dfrac{8u}{9}$",
        r"$v_{A2} = \tfrac{8}{9}u$",
        "v_B2 = 20u/9",
        r"$$v_{B2} = \frac{20}{9}u$$",
        "v_B2 ≈ 2.22u",
        "v_A2 = 0.889u",
        "v_A2 = 0.889 u m/s",
        "KE lost = 20mu²/27",
        "KE lost = 20mu^2/27",
        r"$\Delta KE = \frac{20}{27}mu^2$",
        r"$\Delta KE = \frac{20mu^{2}}{27}$",
        r"$2m \cdot 2u = 2m v_{A2} + m v_{B2}$",
        r"$v_{A2} = \frac{8}{9} u \text{ m s}^{-1}$",
        "v_A2 = 8u/9 ms^-1",
        "v_B2 = (20/9)u ≈ 2.2u",
        "v_B2 = 20u/9 = 2.22u",
        r"$v_{B2} = \frac{20u}{9} \approx 2.22u$",
        "4mu = 2m(8u/9) + m(20u/9)",
        r"v_A2 = \frac{8}{9}u",
        "v_B2 = 2 2/9 u",
        r"so v_{A2} = \dfrac{8u}{9} m/s, as required",
        r"momentum: 2m \cdot 2u = 2m v_{A2} + m v_{B2}",
        "2m × 2u + m × 0 = 2m × v_A2 + m × v_B2",
        r"$(2m)(2u) + (m)(0) = (2m)v_{A2} + (m)v_{B2}$",
        "v_B2 - v_A2 = 2/3(2u - 0)",
        "v_A2 = 8u ÷ 9",
        "KE lost = 1/2(2m)(2u)^2 - 1/2(2m)(8u/9)^2 - 1/2 m (20u/9)^2 = 20mu^2/27",
        r"$\Delta KE = \frac{1}{2}(2m)(2u)^2 - \frac{1}{2}(2m)\left(\frac{8u}{9}\right)^2 - \frac{1}{2}m\left(\frac{20u}{9}\right)^2 = \frac{20}{27}mu^2$",
        "KE lost = 0.741 m u^2",
        "impulse on B = m(20u/9) = 20mu/9",
        "u_A = 2u, u_B = 0\n2m(2u) = 2mv_A + mv_B\nv_B - v_A = 2/3 × 2u\nv_A = 8u/9, v_B = 20u/9",
    ],
    OBLIQUE: [
        "v_A1n = 5cos37.6° = 3.96 m/s",
        "v_A1n = 5 cos(37.6°) = 3.961",
        r"$v_{A1n} = 5\cos 37.6^\circ = 3.96\ \mathrm{m/s}$",
        "v_A1t = 5 sin 37.6 deg = 3.05",
        "v_B1n = −15 cos 37.6° = −11.9 m/s",
        r"$v_{B1t} = -15\sin(37.6^{\circ}) = -9.15$",
        "v_A2t = v_A1t = 3.05 m/s",
        "20(3.96) + 5(−11.88) = 20v_A2n + 5v_B2n",
        "20 × 3.961 − 5 × 11.88 = 19.8",
        r"$20(3.961) + 5(-11.884) = 20v_{A2n} + 5v_{B2n}$",
        "v_B2n − v_A2n = 0.6(3.961 + 11.884) = 9.51",
        r"$e = \frac{v_{B2n} - v_{A2n}}{v_{A1n} - v_{B1n}}$",
        "25 v_A2n = 19.81 - 47.54 = -27.73",
        "v_A2n = -1.11 m/s",
        "v_A2n ≈ −1.109 m s⁻¹",
        "v_B2n = 8.40 m/s",
        r"$v_{B2n} \approx 8.40\,\mathrm{m\,s^{-1}}$",
        "v_A2 = sqrt(1.109^2 + 3.051^2) = 3.25 m/s",
        "v_A2 = √(1.109² + 3.051²) ≈ 3.25 m/s",
        r"$v_{A2} = \sqrt{(-1.109)^2 + 3.051^2} = 3.25$",
        r"$v_{A1n} = 5\cos(37.6°) = 3.96$",
        r"$v_{A1n} = 5\cos{37.6^{\circ}} = 3.96$",
        "v_A1n = 5 cos 37.6^o = 3.96",
        "v_A1n = 5cos(37.6) = 3.96",
        r"$v_{A2} = \sqrt{1.109^2+3.051^2} = 3.25\,\mathrm{m/s}$",
        "v_A2 = (1.109^2 + 3.051^2)^0.5 = 3.25",
        "v_A2 = (1.109² + 3.051²)^½ = 3.25",
        "v_A2n = -1.11 m/s, v_A2t = 3.05 m/s",
        "v_B2t = v_B1t = -9.15",
        "v_A2 = 3.05 e_t − 1.11 e_n",
        r"$\vec v_{A2} = 3.05\,\hat e_t - 1.11\,\hat e_n$ m/s",
        "v_B2 = −9.15 e_t + 8.40 e_n",
        "v_A1n = 5 × cos 37.6° = 3.96",
        r"$v_{A1n} = 5\cos\left(37.6^\circ\right) = 3.96\,\mathrm{m\,s^{-1}}$",
        r"$v_{A1n} = 5\cos(37.6\degree) = 3.96$",
        "v_A1n = 5 cos(37.6 degrees) = 3.96",
        "v_B2n - v_A2n = 0.6[3.961 - (-11.884)]",
        "v_A2n = -1.11 m/s (i.e. A moves back along n)",
        "|v_A2| = sqrt(1.109² + 3.051²) = 3.25 m/s",
        "A's speed after = 3.25 m/s",
        r"$|\vec{v}_{A2}| = \sqrt{3.051^2 + 1.109^2} = 3.25\ \mathrm{m/s}$",
        "let a = v_A2n, b = v_B2n\n20a + 5b = 19.8\nb - a = 9.51\na = -1.11, b = 8.40",
        "(v_B)_n' - (v_A)_n' = 0.6(3.961 + 11.884) = 9.51",
        r"$(v_A)_t' = 3.051$ m/s",
        "(v_A)_{2t} = 3.051",
        # column vectors (n first, then t), and a unit vector's hat in bold
        r"$$\mathbf{v}_{A2} = \begin{pmatrix} -1.109 \\ 3.051 \end{pmatrix}$$",
        r"\[ \mathbf{v}_{A2} = \begin{bmatrix} -1.109 \\ 3.051 \end{bmatrix} \]",
        "\\begin{align*}\n\\mathbf{v}_{A2} &= \\begin{pmatrix} -1.109 \\\\ 3.051 \\end{pmatrix} \\\\\n"
        "\\mathbf{v}_{B2} &= \\begin{pmatrix} 8.398 \\\\ -9.152 \\end{pmatrix}\n\\end{align*}",
        r"$\mathbf{v}_{A2} = \left(\begin{array}{c} -1.109 \\ 3.051 \end{array}\right)$",
        r"$\mathbf{u}_{A} = \binom{3.961}{3.051}$",
        r"$\vec v_{A2} = -1.109\,\mathbf{\hat n} + 3.051\,\mathbf{\hat t}$",
    ],
}

WRONG: dict[str, list[str]] = {
    DIRECT: [
        "v_B2 - v_A2 = 0.5(12 + 4)",
        "4*12 + 8*4 = 8v_A2 + 4v_B2",
        "v_A2 = 5 m/s",
        "KE lost = 32 J",
        r"$v_{B2} = 6\,\mathrm{m\,s^{-1}}$",
        "v_A2 = 4 ms^-1, v_B2 = 4 ms^-1",
        "T_1 = 3.7 x 10^2 J",
        "KE before = 4.0 × 10^2 J",
        r"$v_{A2} = 5\,\mathrm{m\,s^{-1}}$",
        "v_A2 = 48/12 = 5",
        "v_A2 = 4 m/s & v_B2 = 9 m/s",
        "(v_B)_2 - (v_A)_2 = 0.5[(v_A)_1 + (v_B)_1]",
        "4(12) + 8(4) = 8 (v_A)' + 4 (v_B)'",
        "(vA)2 = 5 m/s",
        "(vA)2 = 4 m/s <-",
        r"$v_{A2}=5\,\mathrm{m}/\mathrm{s}$",
        "v<sub>A2</sub> = 5 m/s",
        "v'_A = 5 m/s",
        r"$v_{A}^{\prime} = 5$",
        "v_A2 ~ 5 m/s",
        "v_A2 = 5 m/s   // A carries on",
        "KE lost = 352 J − 280 J = 72 J",
        "4 x 12 + 8 x 4 = 8 x v_A2 + 4 x v_B2",
        "KE before = 0.5x4x12^2 + 0.5x8x4^2 = 288 J",
        "KE after = 0.5x4.0x4.0^2 + 0.5x8.0x8.0^2 = 352 J",
        "$v_{A2} = 5 m/s$",
        r"$v_{B2} = 6\ ms^{-1}$",
        "v_{B2} = 6",
    ],
    WALL: [
        "v_A2 = -0.6 × 4 = -2.4 m/s",
        "KE lost = 16 J",
        "rebound speed = 1.2 m/s",
        "impulse = 2(4 − 1.6) = 4.8 N s",
        "impulse = 4.8 N s",
        r"$KE_{lost} = 16\,\mathrm{J}$",
        "speed after = 2.4 m/s",
    ],
    SYMBOLIC: [
        r"v_A2 = \frac{8}{3}u",
        "v_B2 = 2 1/9 u",
        "v_A2 = 2u/3",
        "v_B2 = 8u/3",
        r"$v_{B2} = \frac{8u}{3}$",
        "KE lost = 2mu²/3",
    ],
    OBLIQUE: [
        "v_A1n = 5 sin 37.6° = 3.05",
        "v_A2n = 1.11 m/s",
        "v_B2n − v_A2n = 0.6(3.961 − 11.884)",
        "v_A2 = sqrt(1.109^2 + 3.051^2) = 4.16",
        "v_A2 = 3.05 e_t − 2.11 e_n",
        "A's speed after = 3.52 m/s",
        r"$\mathbf{v}_{A2} = \begin{pmatrix} 3.051 \\ -1.109 \end{pmatrix}$",  # n and t swapped
        r"$\mathbf{u}_{A} = \binom{3.051}{3.961}$",
    ],
}

#: Classes still misjudged (the breadth figure counts them as failures): text -> why.
NOT_YET = {
    "taking away from the wall as positive\nv_A1 = -4, v_A2 = 1.6": (
        "a convention declared in words does not turn derive's own names (v_A1) round (names area)"
    ),
}

CASES = [
    pytest.param(p, t, v, marks=pytest.mark.xfail(strict=True, reason=NOT_YET[t])) if t in NOT_YET else (p, t, v)
    for v, table in (("correct", CORRECT), ("wrong", WRONG))
    for p, ts in table.items()
    for t in ts
]


@functools.cache
def _solution(problem: str):
    return derive.solve(derive.load(problem))


def _statuses(problem: str, text: str) -> list[str]:
    report = derive.check(_solution(problem), derivation=text)
    return [i.status for i in report.items if i.kind == "line"]


@pytest.mark.parametrize(("problem", "text", "verdict"), CASES)
def test_a_relation_typed_as_students_type_it_is_judged(problem: str, text: str, verdict: str) -> None:
    got = _statuses(problem, text)
    if verdict == "correct":
        assert got and all(s == "correct" for s in got), got
    else:
        assert "wrong" in got, got
