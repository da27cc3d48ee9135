package org.tensim.solver.integrators;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;
import org.tensim.solver.Integrator;
import org.tensim.solver.MidpointRK2;
import org.tensim.solver.prefactored.PrefactoredBdf2;

/**
 * The project's one catalogue of integrators: every named setup (a method with its settings), by name. It is
 * the single source of the names and their order for command lines and their help, the GUI's menu, presets,
 * sweep and calibration specs, the studies and the tests; of each method's stability description
 * ({@link Integrator#stability()}); and of the real-time setting ({@link #REAL_TIME} at
 * {@link #REAL_TIME_STEP_S}).
 *
 * <p>Two kinds of entry:
 * <ul>
 * <li><b>methods</b> ({@link #names()}): one per class, with its default settings; the name is the
 * integrator's own {@link Integrator#name()}. Studies and tests enumerate these, so a new method is tested
 * at once;</li>
 * <li><b>variants</b>: a method with other settings, under a name of its own:
 * {@value #REAL_TIME_IMPLICIT}, {@value #LARGE_STEP_ACCURATE}, {@value #CONTACT} and {@value #CONTACT_REAL_TIME}.</li>
 * </ul>
 * {@link #create(String)} and {@link #choice(String)} accept both kinds ({@link #choiceNames()}). Adding a
 * method is one line here and one class; adding a variant is one line here.
 */
public final class Integrators {
    /** The paper's integrator, the default of every command. */
    public static final String DEFAULT = "rk2";
    /**
     * Implicit Euler with its CG stopped at a relative residual of {@link #REAL_TIME_CG_TOLERANCE}: the setting
     * of the real-time study on coarse models (docs/diaphragm.md); the method {@code implicit-euler} solves to
     * 1e-12, for accuracy studies.
     */
    public static final String REAL_TIME_IMPLICIT = "implicit-euler-cg1e-3";
    /** CG tolerance of {@link #REAL_TIME_IMPLICIT}, relative residual. */
    public static final double REAL_TIME_CG_TOLERANCE = 1e-3;
    /**
     * The large-step solver for real time ({@link PrefactoredBdf2}: BDF2, Newton-CG preconditioned by a
     * prefactored sparse Cholesky, refactored in the background after a change) with its default iterations,
     * at {@link #REAL_TIME_STEP_S}: the setting of {@code diaphragm --realtime} with the fibres' load and the
     * one the GUI opens the diaphragm with (docs/diaphragm.md, docs/gui.md).
     */
    public static final String REAL_TIME = PrefactoredBdf2.NAME;
    /**
     * Time step of {@link #REAL_TIME}, s: 25 ms, the largest step the real-time study found within its
     * tolerance of RK2 on the default mesh with the fibres (docs/diaphragm.md).
     */
    public static final double REAL_TIME_STEP_S = 0.025;
    /**
     * {@link #REAL_TIME} with {@link #LARGE_STEP_ACCURATE_NEWTON} Newton iterations of up to
     * {@link #LARGE_STEP_ACCURATE_KRYLOV} CG iterations a step: closer to RK2 than one Newton iteration at
     * 10-20 ms steps, for about three times the cost of a step (docs/diaphragm.md, real-time study).
     */
    public static final String LARGE_STEP_ACCURATE = "bdf2-newton2";
    /** Newton iterations per step of {@link #LARGE_STEP_ACCURATE}. */
    public static final int LARGE_STEP_ACCURATE_NEWTON = 2;
    /** CG iterations per Newton iteration of {@link #LARGE_STEP_ACCURATE}. */
    public static final int LARGE_STEP_ACCURATE_KRYLOV = 8;
    /**
     * {@link #REAL_TIME} converged for stiff one-sided contact (a diaphragm sliding on bone surfaces,
     * docs/thorax.md): {@link PrefactoredBdf2#CONTACT_NEWTON_ITERATIONS} Newton iterations of up to
     * {@link PrefactoredBdf2#CONTACT_KRYLOV_ITERATIONS} CG iterations a step, at {@link #CONTACT_STEP_S}.
     */
    public static final String CONTACT = "bdf2-contact";
    /** The step the thorax was measured stable and converged at with {@link #CONTACT}, s. */
    public static final double CONTACT_STEP_S = 0.005;

    /**
     * The real-time setting where stiff contact acts (a diaphragm sliding on bone surfaces, docs/thorax.md, "Real
     * time in the thorax"): {@link #REAL_TIME} at {@link #REAL_TIME_STEP_S} with {@link #CONTACT_REAL_TIME_NEWTON}
     * Newton iterations of up to {@link #CONTACT_REAL_TIME_KRYLOV} CG iterations and the rigid links tied in the
     * preconditioner ({@link PrefactoredBdf2#CONTACT_LINK_COUPLING}).
     */
    public static final String CONTACT_REAL_TIME = "bdf2-contact-realtime";
    /** Newton iterations per step of {@link #CONTACT_REAL_TIME}. */
    public static final int CONTACT_REAL_TIME_NEWTON = 1;
    /** CG iterations per Newton iteration of {@link #CONTACT_REAL_TIME}. */
    public static final int CONTACT_REAL_TIME_KRYLOV = 8;

    private static final Map<String, Supplier<Integrator>> METHODS = new LinkedHashMap<>();
    private static final Map<String, IntegratorChoice> BY_NAME = new LinkedHashMap<>();

    static {
        METHODS.put("euler", ExplicitEuler::new);
        METHODS.put("symplectic-euler", SymplecticEuler::new);
        METHODS.put("rk2", MidpointRK2::new);
        METHODS.put("heun", Heun::new);
        METHODS.put("verlet", VelocityVerlet::new);
        METHODS.put("rk4", RK4::new);
        METHODS.put("implicit-euler", ImplicitEuler::new);
        METHODS.put(PrefactoredBdf2.NAME, PrefactoredBdf2::new);
        for (Map.Entry<String, Supplier<Integrator>> e : METHODS.entrySet()) {
            String n = e.getKey();
            String label = n + ", order " + e.getValue().get().order() + (n.equals(DEFAULT) ? " (paper)"
                    : n.equals(REAL_TIME) ? " (large steps, real time)" : "");
            add(new IntegratorChoice(n, label, e.getValue()));
        }
        add(new IntegratorChoice(REAL_TIME_IMPLICIT, "implicit-euler, CG to 1e-3 (real time on coarse models)",
                () -> new ImplicitEuler().setTolerance(REAL_TIME_CG_TOLERANCE)));
        add(new IntegratorChoice(LARGE_STEP_ACCURATE, "bdf2, 2 Newton x 8 CG (large steps, within 2 % of RK2)",
                () -> new PrefactoredBdf2().setNewtonIterations(LARGE_STEP_ACCURATE_NEWTON)
                        .setKrylovIterations(LARGE_STEP_ACCURATE_KRYLOV)));
        add(new IntegratorChoice(CONTACT, "bdf2, 3 Newton x 20 CG (contact with bone surfaces)",
                () -> new PrefactoredBdf2().setNewtonIterations(PrefactoredBdf2.CONTACT_NEWTON_ITERATIONS)
                        .setKrylovIterations(PrefactoredBdf2.CONTACT_KRYLOV_ITERATIONS)));
        add(new IntegratorChoice(CONTACT_REAL_TIME, "bdf2, 1 Newton x 8 CG, links tied in the preconditioner (contact"
                + " with bone surfaces at 25 ms)", () -> new PrefactoredBdf2()
                        .setNewtonIterations(CONTACT_REAL_TIME_NEWTON).setKrylovIterations(CONTACT_REAL_TIME_KRYLOV)
                        .setLinkCoupling(PrefactoredBdf2.CONTACT_LINK_COUPLING)));
    }

    private Integrators() {
    }

    private static void add(IntegratorChoice c) {
        if (BY_NAME.putIfAbsent(c.name(), c) != null) {
            throw new IllegalStateException("integrator name declared twice: " + c.name());
        }
    }

    /** The methods' names, in a fixed order (lowest order first); each with its default settings. */
    public static List<String> names() {
        return List.copyOf(METHODS.keySet());
    }

    /** Every setup's name: the methods ({@link #names()}), then the variants. */
    public static List<String> choiceNames() {
        return List.copyOf(BY_NAME.keySet());
    }

    /** Every setup, the default ({@link #DEFAULT}) first, then {@link #choiceNames()}'s order: a menu. */
    public static List<IntegratorChoice> choices() {
        List<IntegratorChoice> l = new ArrayList<>(BY_NAME.values());
        l.remove(BY_NAME.get(DEFAULT));
        l.add(0, BY_NAME.get(DEFAULT));
        return List.copyOf(l);
    }

    /**
     * The setup of that name.
     *
     * @throws IllegalArgumentException naming the unknown name and every known one
     */
    public static IntegratorChoice choice(String name) {
        IntegratorChoice c = name == null ? null : BY_NAME.get(name);
        if (c == null) {
            throw new IllegalArgumentException("unknown integrator '" + name + "': expected one of "
                    + String.join(", ", BY_NAME.keySet()));
        }
        return c;
    }

    /**
     * A new integrator of the setup of that name (a method or a variant).
     *
     * @throws IllegalArgumentException naming the unknown name and every known one
     */
    public static Integrator create(String name) {
        return choice(name).create();
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
     * Every setup's name as an {@link Iterable} with a public no-argument constructor, for command-line
     * libraries that fill help texts from such a class (picocli's {@code completionCandidates}).
     */
    public static final class Names implements Iterable<String> {
        @Override
        public java.util.Iterator<String> iterator() {
            return choiceNames().iterator();
        }
    }
}
