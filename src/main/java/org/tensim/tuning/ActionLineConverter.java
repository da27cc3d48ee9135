package org.tensim.tuning;

import org.tensim.scene.diaphragm.ActionLines;

/** Reads "X,Y,R" in millimetres into an action line in metres. */
final class ActionLineConverter implements picocli.CommandLine.ITypeConverter<ActionLines.Line> {
    @Override
    public ActionLines.Line convert(String value) {
        String[] f = value.split(",");
        if (f.length != 3) {
            throw new picocli.CommandLine.TypeConversionException("expected X,Y,R in mm (three numbers), got '"
                    + value + "'");
        }
        double[] d = new double[3];
        for (int i = 0; i < 3; i++) {
            try {
                d[i] = Double.parseDouble(f[i].trim());
            } catch (NumberFormatException e) {
                throw new picocli.CommandLine.TypeConversionException("expected X,Y,R in mm, '" + f[i].trim()
                        + "' in '" + value + "' is not a number");
            }
        }
        try {
            return new ActionLines.Line(1e-3 * d[0], 1e-3 * d[1], 1e-3 * d[2]);
        } catch (IllegalArgumentException e) {
            throw new picocli.CommandLine.TypeConversionException(e.getMessage() + " (in '" + value + "')");
        }
    }
}
