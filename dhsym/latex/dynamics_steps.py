r"""The derivation of the equations of motion and the regressor in LaTeX: Lagrange's steps (each
link's centre of mass, Jacobians and energies, the derivatives of M, the Lagrangian's derivatives)
or Craig's Newton–Euler passes, and the base parameters with the columns of the base regressor.
The lines are the printers' (dhsym.printing.dynamics_steps), laid out by the documents' one rule.

>>> import dhsym
>>> from dhsym.dynamics.derive import derive
>>> from dhsym.latex.layout import PAGES
>>> from dhsym.printing.dynamics import MotionLatexPrinter
>>> arm = dhsym.load("spong_elbow")
>>> result = derive(arm.chain, arm.filled_masses())
>>> printer = MotionLatexPrinter(arm, result)
>>> [s.title for s in steps_sections(arm, result, PAGES["article"], printer, "lagrange")]
['Lagrange: link 1', 'Lagrange: link 2', 'Lagrange: the derivatives of $M$', "Lagrange's equations"]
"""
from __future__ import annotations

from ..printing.dynamics_steps import grouped_parameters
from .aligned_rows import aligned_rows
from .layout import Page, Rows, paragraph
from .sections import Section

PART = "Dynamics: the derivation"
LAGRANGE = {
    "links": "Each link's centre of mass $r_{ci}$ and its Jacobians in the first frame, its angular velocity in "
             "its own frame, its kinetic energy (the linear and the angular part; $I_{ci}$ is its inertia tensor "
             "about the centre of mass, in frame $i$) and its potential energy $P_i = -m_i g^{T} r_{ci}$.",
    "derivatives": "$K = \\sum_i K_i = \\tfrac{1}{2}\\dot{q}^{T} M \\dot{q}$ and $P = \\sum_i P_i$. The "
                   "derivatives of $M$ that are not zero:",
    "constant": "$K = \\sum_i K_i = \\tfrac{1}{2}\\dot{q}^{T} M \\dot{q}$ and $P = \\sum_i P_i$; $M$ is constant.",
    "equations": "With $L = K - P$, $\\tau_k = \\frac{d}{dt}\\frac{\\partial L}{\\partial \\dot{q}_k} - "
                 "\\frac{\\partial L}{\\partial q_k}$, joint by joint:",
}
NEWTON = {
    "outward": "Outward from the base, which accelerates upward (${}^{0}\\dot{v}_{0} = -g$): each link's "
               "$\\omega$, $\\dot{\\omega}$, the acceleration $\\dot{v}$ of its frame's origin and $\\dot{v}_{C}$ "
               "of its centre of mass $P_{C}$, $F = m\\dot{v}_{C}$ and $N = {}^{C}I\\dot{\\omega} + \\omega "
               "\\times {}^{C}I\\omega$, in its joint frame.",
    "joint frames": "The joint frames are the modified-DH frames of this chain: joint frame $i$ sits on joint "
                    "$i$'s axis (the robot file's frame $i$ sits at the far end of link $i$).",
    "inward": "Inward from the tip: $f_i = F_i + R f_{i+1}$, $n_i = N_i + R n_{i+1} + P_{C_i} \\times F_i + "
              "P_{i+1} \\times R f_{i+1}$; $\\tau_i$ is the $z$ entry of $n_i$ (of $f_i$ for a prismatic joint).",
}
REGRESSOR = {
    "standard": "$\\tau = Y(q, \\dot{q}, \\ddot{q})\\,\\pi$ is linear in $\\pi$, the standard inertial parameters "
                "of each link $i$ about the origin of its frame $i$, along its axes: its inertia "
                "$XX_i, XY_i, XZ_i, YY_i, YZ_i, ZZ_i$, its mass times its centre of mass $MX_i, MY_i, MZ_i$, and "
                "its mass $m_i$. The base parameters, the combinations "
                "$\\tau$ identifies (Gautier and Khalil's grouping), so that $\\tau = Y_b\\,\\pi_b$:",
    "alone": "On their own (nothing grouped into them): ${names}$.",
    "moves none": "They move no joint: ${names}$.",
    "columns": "The columns of $Y_b$:",
    "too large": "The columns of $Y_b$ would have about {terms:,} terms multiplied out, more than dhsym writes out.",
}


def _rows(printer, records, page: Page) -> Rows:
    """Each record's lines, one element each, broken to the page."""
    return aligned_rows([[pair for record in records for pair in printer.lines(record)]], page)


def steps_sections(robot, result, page: Page, printer, method: str = "lagrange") -> list[Section]:
    """Lagrange's steps or Craig's passes, a section per link."""
    chain, masses, numbering = robot.chain, robot.filled_masses(), robot.numbering
    if method == "lagrange":
        from ..dynamics.lagrange_steps import lagrange_steps

        steps = lagrange_steps(chain, masses, result)
        out = [Section(PART, f"Lagrange: link {numbering.frame(step.link)}",
                       ([paragraph(LAGRANGE["links"], page)] if k == 0 else []) + [_rows(printer, [step], page)])
               for k, step in enumerate(steps.links)]
        out.append(Section(PART, "Lagrange: the derivatives of $M$",
                           [paragraph(LAGRANGE["derivatives"], page), _rows(printer, steps.derivatives, page)]
                           if steps.derivatives else [paragraph(LAGRANGE["constant"], page)]))
        out.append(Section(PART, "Lagrange's equations", [paragraph(LAGRANGE["equations"], page),
                                                         _rows(printer, steps.equations, page)]))
        return out
    from ..dynamics.craig_steps import newton_euler_steps

    steps = newton_euler_steps(chain, masses)
    out = []
    for k, (step, centre, inertia) in enumerate(zip(steps.outward, steps.centres, steps.inertias)):
        number = numbering.frame(step.link)
        intro = [paragraph(NEWTON["outward"], page)] + ([] if steps.own_frames else
                                                        [paragraph(NEWTON["joint frames"], page)])
        about = paragraph(f"$P_{{C_{{{number}}}}} = {printer.vector(centre)}$, ${{}}^{{C}}I_{{{number}}}$ "
                          f"$= {printer.vector(inertia)}$ ($I_{{xx}}, I_{{yy}}, I_{{zz}}, I_{{xy}}, I_{{xz}}, "
                          "I_{yz}$).", page)
        out.append(Section(PART, f"Newton--Euler: link {number}, outward",
                           (intro if k == 0 else []) + [about, _rows(printer, [step], page)]))
    out.append(Section(PART, "Newton--Euler: inward", [paragraph(NEWTON["inward"], page),
                                                       _rows(printer, steps.inward[::-1], page)]))
    return out


def regressor_sections(robot, page: Page, printer) -> list[Section]:
    """The base parameters and the columns of the base regressor."""
    from ..dynamics.identification import identification

    found = identification(robot.chain, robot.filled_masses(), robot.numbering.first_joint)
    grouped, alone = grouped_parameters(found)
    items = [paragraph(REGRESSOR["standard"], page), _rows(printer, grouped, page)]
    if alone:
        items.append(paragraph(REGRESSOR["alone"].replace("{names}", ", ".join(printer.doprint(p.symbol)
                                                                              for p in alone)), page))
    if found.unidentifiable:
        names = ", ".join(printer.doprint(p) for p in found.unidentifiable)
        items.append(paragraph(REGRESSOR["moves none"].replace("{names}", names), page))
    out = [Section("Dynamics: the regressor", "Base parameters", items)]
    columns = [paragraph(REGRESSOR["columns"], page), _rows(printer, found.columns, page)] if found.columns else \
        [paragraph(REGRESSOR["too large"].format(terms=found.terms), page)]
    out.append(Section("Dynamics: the regressor", "The base regressor $Y_b$", columns))
    return out
