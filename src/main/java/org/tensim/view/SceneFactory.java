package org.tensim.view;

/**
 * Makes fresh instances of one scene, for a start, a reset, or a change that
 * needs a new topology (the tendon's model). Creation may take time (mesh
 * loading): it is called on the simulation thread, never on the Swing thread.
 */
public interface SceneFactory {
    /** The scene's name, as {@link ViewScene#name()}. */
    String name();

    /**
     * Whether the tendon can be switched between mass-spring and tensegrity. False
     * for the cube, which shows both side by side.
     */
    boolean hasTendonChoice();

    /**
     * A new scene at rest, with its parameters at their defaults.
     *
     * @param tensegrityTendon true: the tendon has rigid links; ignored without a tendon choice
     */
    ViewScene create(boolean tensegrityTendon);
}
