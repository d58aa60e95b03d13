"""A kinetic energy written by its bare name (``KE``, ``E_k``, ``K.E.``) under a label that says
its instant (``Kinetic energy after: E_k = …``, ``**K.E. lost:** KE = …``) is the energy the label
names, not the energy before (derive/checking/energyinstants.py). Expected values by hand."""

from __future__ import annotations

from support.checked import lines

#: OCR M2 2012: 0.8 kg at 4 m/s into a wall, e = 0.3: it rebounds at 1.2 m/s;
#: T_1 = ½(0.8)(16) = 6.4 J, T_2 = ½(0.8)(1.44) = 0.576 J, lost 5.824 J.
WALL = "ocr-m2-2012-particle-hits-wall"
#: OpenStax 8.5: a 0.150 kg puck at 35.0 m/s caught by a 70.0 kg goalie: V = 5.25/70.15 = 0.07484 m/s,
#: T_2 = ½(70.15)(0.07484)² = 0.1965 J.
GOALIE = "openstax-cp-8-5-goalie-catches-puck"


def test_energy_after_without_its_half_is_ke_formula() -> None:
    work = "v = 0.3(4) = 1.2\nKinetic energy after: E_k = 0.8(1.2)^2 = 1.152 J\n"
    assert lines(WALL, work)[2][:2] == ("wrong", "ke_formula")  # 2 x 0.576, the half left out


def test_energy_lost_under_its_label_is_the_loss() -> None:
    work = "$v = 1.2$ m/s\n\n**K.E. lost:** $KE = \\tfrac12(0.8)(4^2 - 1.2^2) = 5.824$ J\n"
    assert lines(WALL, work)[3][0] == "correct"  # 6.4 - 0.576, not the 6.4 before


def test_final_energy_phone_typed() -> None:
    work = "0.15*35 = 70.15V\nV = 0.0748\nfinal KE: KE = 70.15*0.0748^2 = 0.393\n"
    assert lines(GOALIE, work)[3][:2] == ("wrong", "ke_formula")  # 2 x 0.1965
