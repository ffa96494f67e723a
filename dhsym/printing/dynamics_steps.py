"""The derivation of the equations of motion, written: Lagrange's steps (each link's centre of mass,
Jacobians and energies, the derivatives of M, the Lagrangian's derivatives by name) and Craig's
Newton–Euler passes, link by link. The records come from dhsym.dynamics.lagrange_steps and
craig_steps; this mixin gives the text and the LaTeX printer of dhsym.printing.dynamics their
lines, each a (left side, right side) pair, so that both write them from one place.

Names: rc1, Jvc1, Jω1, ¹ω₁, Ic1 (the inertia tensor about the centre of mass), P1, ∂d11/∂θ2; Craig's
¹ω̇₁, ¹v̇₁, ¹v̇C1, ¹F₁, ¹N₁, ¹f₁, ¹n₁ (LaTeX r_{c1}, J_{v_{c1}}, {}^{1}\\dot{\\omega}_{1}, …).
"""
from __future__ import annotations

from .names import subscript, superscript

HALF = {"unicode": "½ ", "ascii": "1/2 ", "latex": "\\tfrac{1}{2}\\, "}
TRANSPOSE = {"unicode": "ᵀ", "ascii": "^T", "latex": "^{T}"}
# symbol: (unicode, ascii, latex) of Craig's vectors
VECTORS = {"omega": ("ω", "w", "\\omega"), "omega_dot": ("ω̇", "wdot", "\\dot{\\omega}"),
           "acceleration": ("v̇", "vdot", "\\dot{v}"), "com_acceleration": ("v̇C", "vCdot", "\\dot{v}_{C}"),
           "F": ("F", "F", "F"), "N": ("N", "N", "N"), "f": ("f", "f", "f"), "n": ("n", "n", "n")}


class MotionSteps:
    """The lines of the derivation's records; mixed into the dynamics printers, which give `name`,
    `doprint`, `style` and `first` (the printed number of joint 1)."""

    def lines(self, record) -> list[tuple[str, str]]:
        """The (left, right) pairs a record prints as: one for the results, several for a step."""
        method = getattr(self, f"_lines_{type(record).__name__}", None)
        return method(record) if method else [self.sides(record)]

    def _joined(self, record) -> str:
        return "\n".join(f"{left} = {right}" for left, right in self.lines(record))

    _print_LinkEnergyStep = _print_MassDerivative = _print_LagrangeEquation = _joined
    _print_OutwardStep = _print_InwardStep = _print_BaseParameter = _print_RegressorColumn = _joined

    # ---------------------------------------------------------------- names

    def sub_name(self, letter: str, sub: str, link: int) -> str:
        """rc1 (r_{c1}), Ic1, Jvc1 (J_{v_{c1}}), Jω1 (J_{\\omega_{1}})."""
        number = str(link + self.first - 1)
        if self.style == "latex":
            inner = {"ω": "\\omega"}.get(sub, sub)
            return f"{letter}_{{{inner}_{{{number}}}}}" if letter == "J" else f"{letter}_{{{sub}{number}}}"
        return letter + ({"ω": "w"}.get(sub, sub) if self.style == "ascii" else sub) + number

    def frame_vector(self, kind: str, link: int, frame: int | None = None) -> str:
        """¹ω₁ (the vector of link 1 in frame 1), ¹v̇C1, {}^{1}\\dot{\\omega}_{1}; 1w1 in ASCII."""
        text, ascii_text, latex = VECTORS[kind]
        number = str(link + self.first - 1)
        seen = str((link if frame is None else frame) + self.first - 1)
        if self.style == "latex":
            if kind == "com_acceleration":
                return f"{{}}^{{{seen}}}\\dot{{v}}_{{C_{{{number}}}}}"
            return f"{{}}^{{{seen}}}{latex}_{{{number}}}"
        if self.style == "ascii":
            return f"{seen}{ascii_text}{number}"
        if kind == "com_acceleration":
            return f"{superscript(seen)}v̇C{number}"
        return f"{superscript(seen)}{text}{subscript(number)}"

    def vector(self, values) -> str:
        """(a, b, c): plain brackets, which a layout may break a line inside."""
        return "(" + (",\\; " if self.style == "latex" else ", ").join(self.doprint(x) for x in values) + ")"

    def columns(self, matrix) -> str:
        """A 3 × n matrix by its columns, a column of zeros as 0: [(…), (…), 0]."""
        return "[" + (",\\;\\; " if self.style == "latex" else ", ").join(
            self.vector(matrix[:, c]) if any(matrix[:, c]) else "0" for c in range(matrix.cols)) + "]"

    def partial(self, i: int, j: int, variable) -> str:
        """∂d12/∂θ2 (\\frac{\\partial d_{12}}{\\partial \\theta_{2}})."""
        if self.style == "latex":
            return f"\\frac{{\\partial {self.name('d', i, j)}}}{{\\partial {self.doprint(variable)}}}"
        mark = "d" if self.style == "ascii" else "∂"
        return f"{mark}{self.name('d', i, j)}/{mark}{self.doprint(variable)}"

    # ---------------------------------------------------------------- Lagrange

    def _lines_LinkEnergyStep(self, step):
        rates = "qdot" if self.style == "ascii" else "\\dot{q}" if self.style == "latex" else "q̇"
        half, t = HALF[self.style], TRANSPOSE[self.style]
        com, jv, jw = self.sub_name("r", "c", step.link), self.sub_name("J", "vc", step.link), \
            self.sub_name("J", "ω", step.link)
        if self.style == "latex":
            jv = f"J_{{v_{{c{step.link + self.first - 1}}}}}"
        omega, inertia = self.frame_vector("omega", step.link), self.sub_name("I", "c", step.link)
        mass = self.doprint(self._mass(step))
        return [(com, self.vector(step.com)), (jv, self.columns(step.linear)), (jw, self.columns(step.angular)),
                (omega, self.vector(step.omega)),
                (f"{half}{mass} {rates}{t} {jv}{t} {jv} {rates}", half + self.doprint(2 * step.kinetic_linear)),
                (f"{half}{omega}{t} {inertia} {omega}", half + self.doprint(2 * step.kinetic_angular)),
                (self.name("P", step.link), self.doprint(step.potential))]

    def _mass(self, step):
        """m_i as the robot gives it (a number or a name): K's linear part divided by ½ q̇ᵀJᵀJq̇."""
        return self.masses[step.link - 1]

    def _lines_MassDerivative(self, record):
        return [(self.partial(record.i, record.j, record.variable), self.doprint(record.value))]

    def _lines_LagrangeEquation(self, eq):
        k, space = eq.k, "\\," if self.style == "latex" else " "
        def rate(j):
            return self.doprint(eq.rates[j - 1])

        def acceleration(j):
            return self.doprint(eq.accelerations[j - 1])

        q, qd = self.doprint(eq.variables[k - 1]), rate(k)
        if self.style == "latex":
            d_dqdot, d_dq = f"\\frac{{\\partial L}}{{\\partial {qd}}}", f"\\frac{{\\partial L}}{{\\partial {q}}}"
            d_dt = f"\\frac{{d}}{{dt}} {d_dqdot}"
        else:
            mark = "d" if self.style == "ascii" else "∂"
            d_dqdot, d_dq = f"{mark}L/{mark}{qd}", f"{mark}L/{mark}{q}"
            d_dt = f"d/dt {d_dqdot}"
        momentum = " + ".join(f"{self.name('d', k, j)}{space}{rate(j)}" for j in eq.columns) or "0"
        changing = [f"{self.name('d', k, j)}{space}{acceleration(j)}" for j in eq.columns]
        changing += [f"{self.partial(min(k, j), max(k, j), eq.variables[i - 1])}{space}{self._rate_product(i, j, eq)}"
                     for i, j in eq.changing]
        slopes = [f"{HALF[self.style] if i == j else ''}{self.partial(i, j, eq.variables[k - 1])}{space}"
                  f"{self._rate_product(i, j, eq)}" for i, j in eq.slopes]
        slope = " + ".join(slopes) + (f" − {self.name('φ', k)}" if eq.gravity else "")
        slope = slope.replace(" − ", " - ") if self.style != "unicode" else slope
        if eq.gravity and not slopes:
            slope = ("−" if self.style == "unicode" else "-") + self.name("φ", k)
        return [(d_dqdot, momentum), (d_dt, " + ".join(changing) or "0"), (d_dq, slope or "0")]

    def _rate_product(self, i: int, j: int, eq) -> str:
        if i == j:
            return self.doprint(eq.rates[i - 1] ** 2)
        space = "\\," if self.style == "latex" else " "
        return f"{self.doprint(eq.rates[i - 1])}{space}{self.doprint(eq.rates[j - 1])}"

    # ---------------------------------------------------------------- the regressor

    def _lines_BaseParameter(self, record):
        return [(self.doprint(record.symbol), self.doprint(record.value))]

    def _lines_RegressorColumn(self, record):
        name = self.doprint(record.parameter.symbol)
        left = f"\\frac{{\\partial \\tau}}{{\\partial {name}}}" if self.style == "latex" else \
            f"{'d' if self.style == 'ascii' else '∂'}τ/{'d' if self.style == 'ascii' else '∂'}{name}"
        return [(left, self.vector(record.values))]

    # ---------------------------------------------------------------- Newton–Euler

    def _lines_OutwardStep(self, step):
        return [(self.frame_vector(kind, step.link), self.vector(getattr(step, kind)))
                for kind in ("omega", "omega_dot", "acceleration", "com_acceleration")] + \
               [(self.frame_vector("F", step.link), self.vector(step.force)),
                (self.frame_vector("N", step.link), self.vector(step.moment))]

    def _lines_InwardStep(self, step):
        return [(self.frame_vector("f", step.link), self.vector(step.force)),
                (self.frame_vector("n", step.link), self.vector(step.moment)),
                (self.name("τ", step.link), self.doprint(step.torque))]


LAGRANGE_TEXT = {
    "links": "Lagrange's equations (Spong). Each link's centre of mass rci and its Jacobians in the first frame, "
             "its angular velocity in its own frame, its kinetic energy (the linear and the angular part; Ici is "
             "its inertia tensor about the centre of mass, in frame i) and its potential energy Pi = −mi gᵀ rci:",
    "derivatives": "K = Σ Ki = ½ q̇ᵀ M q̇ and P = Σ Pi. The derivatives of M that are not zero:",
    "no derivatives": "K = Σ Ki = ½ q̇ᵀ M q̇ and P = Σ Pi. M is constant: no derivative of it is not zero.",
    "equations": "With L = K − P, τk = d/dt ∂L/∂q̇k − ∂L/∂qk, joint by joint:",
}
NEWTON_TEXT = {
    "outward": "Newton–Euler recursion (Craig). Outward from the base, which accelerates upward (v̇0 = −g): each "
               "link's ω, ω̇, v̇ of its frame's origin, v̇C of its centre of mass PC, F = m v̇C and "
               "N = ᶜI ω̇ + ω × ᶜI ω (ᶜI its inertia tensor about PC), in its joint frame:",
    "joint frames": "The joint frames are the modified-DH frames of this chain: joint frame i sits on joint i's axis "
                    "(the file's frame i sits at the far end of link i).",
    "inward": "Inward from the tip: f = F + R f_next, n = N + R n_next + PC × F + P_next × R f_next; τ is the z "
              "entry of n (of f for a prismatic joint):",
}


def text_steps(steps, printer, width: int, method: str) -> list[str]:
    """The derivation's blocks of text (`steps`: LagrangeSteps or NewtonEulerSteps), lines broken at `width`."""
    from .render import break_element, wrap  # render's helpers build on the printers this mixin joins

    def block(heading: str, records) -> str:
        lines = [wrap(heading, width)] if heading else []
        for record in records:
            lines += [break_element(f"{left} = ", right, width) for left, right in printer.lines(record)]
        return "\n".join(lines)

    if method == "lagrange":
        texts = LAGRANGE_TEXT
        out = [wrap(texts["links"], width)]
        out += [block(f"Link {step.link + printer.first - 1}", [step]) for step in steps.links]
        out.append(block(texts["derivatives"], steps.derivatives) if steps.derivatives
                   else wrap(texts["no derivatives"], width))
        out.append(block(texts["equations"], steps.equations))
        return out
    out = [wrap(NEWTON_TEXT["outward"], width)]
    if not steps.own_frames:
        out.append(wrap(NEWTON_TEXT["joint frames"], width))
    for step, centre, inertia in zip(steps.outward, steps.centres, steps.inertias):
        number = step.link + printer.first - 1
        heading = (f"Link {number}: PC{number} = {printer.vector(centre)}, ᶜI{number} = "
                   f"{printer.vector(inertia)} (Ixx, Iyy, Izz, Ixy, Ixz, Iyz)")
        out.append(block(heading, [step]))
    out.append(block(NEWTON_TEXT["inward"], steps.inward[::-1]))
    return out


REGRESSOR_TEXT = {
    "standard": "Regressor: τ = Y(q, q̇, q̈) π, linear in π, the standard inertial parameters of each link i about "
                "the origin of its frame i, along its axes: XXi, XYi, XZi, YYi, YZi, ZZi (its inertia), MXi, MYi, "
                "MZi (mi times its centre of mass) and mi.",
    "base": "The base parameters, the combinations that τ identifies (Gautier and Khalil's grouping; R marks a "
            "parameter with others grouped into it), so that τ = Yb πb:",
    "moves none": "The standard parameters that move no joint: {names}.",
    "alone": "Base parameters on their own (nothing grouped into them): {names}.",
    "columns": "The columns of Yb:",
    "too large": "The columns of Yb would have about {terms:,} terms multiplied out, more than the {limit:,} dhsym "
                 "writes out; ask for fewer links (--to).",
}


def text_regressor(found, printer, width: int) -> list[str]:
    """The regressor's blocks: what π is, the base parameters, Y_b's columns (or why they are not shown)."""
    from ..dynamics.identification import MAX_REGRESSOR_TERMS
    from .render import break_element, wrap

    def block(heading: str, records) -> str:
        lines = [wrap(heading, width)]
        for record in records:
            lines += [break_element(f"{left} = ", right, width) for left, right in printer.lines(record)]
        return "\n".join(lines)

    grouped, alone = grouped_parameters(found)
    out = [wrap(REGRESSOR_TEXT["standard"], width), block(REGRESSOR_TEXT["base"], grouped)]
    if alone:
        out.append(wrap(REGRESSOR_TEXT["alone"].format(names=", ".join(printer.doprint(p.symbol) for p in alone)),
                        width))
    if found.unidentifiable:
        names = ", ".join(printer.doprint(p) for p in found.unidentifiable)
        out.append(wrap(REGRESSOR_TEXT["moves none"].format(names=names), width))
    if found.columns:
        out.append(block(REGRESSOR_TEXT["columns"], found.columns))
    else:
        out.append(wrap(REGRESSOR_TEXT["too large"].format(terms=found.terms, limit=MAX_REGRESSOR_TERMS), width))
    return out


def grouped_parameters(found) -> tuple[list, list]:
    """(the base parameters with others grouped into them, those that are a standard parameter alone)."""
    grouped = [p for p in found.base if p.value != p.symbol]
    return grouped, [p for p in found.base if p.value == p.symbol]
