r"""The exact algebra beneath screwsym: decisions over Q, number fields and the unit circle.

This floor imports nothing of screwsym; ``core``, ``motion`` and ``systems`` use it.
As SymPy keeps ``polys`` (domains, ``matrices``, ``groebnertools``, ``numberfields``)
beneath ``matrices`` and ``physics``, the procedures that decide ranks, zeros and
signs exactly live here, one module per procedure:

- :mod:`~screwsym.algebra.budget`: the work budget every procedure charges;
- :mod:`~screwsym.algebra.circle`: ``sin(q)``, ``cos(q)`` as two symbols on the unit circle;
- :mod:`~screwsym.algebra.numberfield`: arithmetic over ``Q(theta)`` through ``Q[x, theta]``;
- :mod:`~screwsym.algebra.rings`: expressions as columns of a sparse polynomial ring, and back;
- :mod:`~screwsym.algebra.linalg`: determinants, Cramer's rule, ranks proved, null spaces;
- :mod:`~screwsym.algebra.real`: real zeros and positivity;
- :mod:`~screwsym.algebra.surface`: ranks on a hypersurface, by modular points and Groebner bases.

Every name here is public inside its module (the modules' ``__all__`` list them), for the
floors above and the tests; none is re-exported by ``screwsym`` itself.
"""

__all__: list[str] = []  # the modules' names are reached through the modules
