package org.tensim.solver.integrators;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;
import org.tensim.solver.Integrator;
import org.tensim.solver.MidpointRK2;
import org.tensim.solver.prefactored.PrefactoredBdf2;

/**
 * The integrators by name: the single source of their names and order (command
 * lines, their help, reports, the GUI's menu), of their stability description
 * ({@link Integrator#stability()}) and of the tests' parameter lists (tests enumerate
 * {@link #names()}, so a new method is tested at once). Each call of
 * {@link #create(String)} makes a new instance (integrators keep scratch arrays sized
 * for one state). Adding an integrator is one line here and one class.
 */
public final class Integrators {
    /** The paper's integrator, the default of every command. */
    public static final String DEFAULT = "rk2";

    private static final Map<String, Supplier<Integrator>> BY_NAME = new LinkedHashMap<>();

    static {
        BY_NAME.put("euler", ExplicitEuler::new);
        BY_NAME.put("symplectic-euler", SymplecticEuler::new);
        BY_NAME.put("rk2", MidpointRK2::new);
        BY_NAME.put("heun", Heun::new);
        BY_NAME.put("verlet", VelocityVerlet::new);
        BY_NAME.put("rk4", RK4::new);
        BY_NAME.put("implicit-euler", ImplicitEuler::new);
        BY_NAME.put(PrefactoredBdf2.NAME, PrefactoredBdf2::new);
    }

    private Integrators() {
    }

    /** All names, in a fixed order (lowest order first). */
    public static List<String> names() {
        return List.copyOf(BY_NAME.keySet());
    }

    /**
     * A new integrator of that name.
     *
     * @throws IllegalArgumentException naming the unknown name and the known ones
     */
    public static Integrator create(String name) {
        Supplier<Integrator> s = name == null ? null : BY_NAME.get(name);
        if (s == null) {
            throw new IllegalArgumentException("unknown integrator '" + name + "': expected one of "
                    + String.join(", ", BY_NAME.keySet()));
        }
        return s.get();
    }

    /**
     * The names for a help text, the default marked:
     * {@code "euler, symplectic-euler, rk2 (the paper's), ..."}.
     */
    public static String helpList() {
        StringBuilder b = new StringBuilder();
        for (String n : BY_NAME.keySet()) {
            b.append(b.length() == 0 ? "" : ", ").append(n).append(n.equals(DEFAULT) ? " (the paper's)" : "");
        }
        return b.toString();
    }

    /**
     * The names as an {@link Iterable} with a public no-argument constructor, for
     * command-line libraries that fill help texts from such a class (picocli's
     * {@code completionCandidates}).
     */
    public static final class Names implements Iterable<String> {
        @Override
        public java.util.Iterator<String> iterator() {
            return names().iterator();
        }
    }

    /** Name to supplier, read-only. */
    public static Map<String, Supplier<Integrator>> all() {
        return Collections.unmodifiableMap(BY_NAME);
    }
}
