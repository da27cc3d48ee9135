package org.tensim.sweep;

import java.io.Serializable;

/**
 * One point of a sweep: its number and the swept parameters' values in the spec's order.
 *
 * @param id     0-based number, fixed by the spec (the grid's order, or the Latin hypercube's draw)
 * @param values values in the units of the parameters' keys
 */
public record Point(int id, double[] values) implements Serializable {
    private static final long serialVersionUID = 1L;

    public Point {
        values = values.clone();
    }
}
