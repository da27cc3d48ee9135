package org.tensim.scene.diaphragm;

import java.nio.file.Path;
import java.util.List;
import org.tensim.io.mesh.MeshCleaner;
import org.tensim.io.mesh.MeshUnits;
import org.tensim.model.Vec3;
import org.tensim.scene.shell.TissueModel;

/**
 * The diaphragm's choices as a user states them, each null (false) when left out: the options of
 * {@code tensim diaphragm} ({@code org.tensim.tuning.DiaphragmOptions}, whose descriptions give each one's meaning,
 * unit and default) and the keys of a scene file's {@code type: diaphragm} body. The fields are in the options'
 * units (mm for lengths, Pa, Pa/m, s). {@link #spec} turns them into the one {@link DiaphragmSpec}, with one
 * validation, whichever way they came in; messages name the options ({@code --thickness}).
 */
public final class DiaphragmChoices {
    public Path mesh;
    public String units;
    public Double thicknessMm;
    public Integer rings;
    public Path boxes;
    public Path thorax;
    public String cage;
    public Path labels;
    public TendonRule tendonRule;
    public Boolean contact;
    public Double contactPaPerM;
    public Double liverPaPerM;
    public Double abdominalPaPerM;
    public Double abdominalPressurePa;
    public Double appositionPa;
    public String model;
    public Double ribAmplitude;
    public Double musclePa;
    public Double periodS;
    public Double ieRatio;
    public Double pauseShare;
    public Double attachMm;
    public BoundaryConditions.Attachment attachment;
    public Double bandPaPerM;
    public boolean allSegments;
    public BoundaryConditions.MuscleLoad muscleLoad;
    public Double weldMm;
    public Double minPieceFraction;
    public double[] tendonNormal;
    public double[] tendonPointMm;
    public Double tendonFraction;
    public TissueModel tissueModel;
    public List<ActionLines.Line> actionLines;

    /**
     * The scene these options describe: the default (or the paper's) spec with every given option applied.
     *
     * @param defaultMesh  the mesh file read when {@code --mesh} is left out (null: the generated double dome)
     * @param defaultRings the generated double dome's rings when {@code --rings} is left out
     * @throws IllegalArgumentException naming the option and the value when one is out of range or the options
     *                                  contradict each other
     */
    public DiaphragmSpec spec(Path defaultMesh, int defaultRings) {
        boolean paper = paperModel();
        DiaphragmSpec base = paper ? DiaphragmSpec.paper() : DiaphragmSpec.defaults();
        if (paper) {
            for (Object[] o : new Object[][] {{"--tissue-model", tissueModel}, {"--attachment", attachment},
                    {"--muscle-load", muscleLoad}}) {
                if (o[1] != null) {
                    throw new IllegalArgumentException("--model paper sets " + o[0] + " itself (the paper's); leave"
                            + " it out or use --model default");
                }
            }
        }
        DiaphragmParameters p = base.tissue();
        if (attachMm != null) {
            p = p.withAttachThreshold(attachMm * 1e-3);
        }
        if (tendonFraction != null) {
            p = p.withTendonAreaFraction(tendonFraction);
        }
        if (tissueModel != null) {
            p = p.withTissueModel(tissueModel);
        }
        if (abdominalPaPerM != null) {
            try {
                p = p.withAbdominalSupport(abdominalPaPerM);
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException("--abdominal-support: " + e.getMessage(), e);
            }
        }
        if (tendonNormal != null || tendonPointMm != null) {
            Vec3 normal = tendonNormal == null ? p.tendonNormal() : vector("--tendon-normal", tendonNormal, 1);
            Vec3 point = tendonPointMm == null ? null : vector("--tendon-point", tendonPointMm, 1e-3);
            p = p.withTendonPlane(normal, point);
        }
        BoundaryConditions b = base.boundary();
        try {
            b = new BoundaryConditions(attachment == null ? b.attachment()
                    : attachment,
                    bandPaPerM == null ? b.bandStiffnessPaPerM() : bandPaPerM, b.bandTaperM(),
                    muscleLoad == null ? b.muscleLoad()
                            : muscleLoad,
                    !allSegments && b.costalOriginsOnly());
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("--attachment, --band-stiffness, --muscle-load: " + e.getMessage(), e);
        }
        if (actionLines != null && !actionLines.isEmpty() && b.muscleLoad() == BoundaryConditions.MuscleLoad.FIBRES) {
            throw new IllegalArgumentException("--action-line: the muscle load '" + BoundaryConditions.name(
                    b.muscleLoad()) + "' (the active fibre tension) has no action lines; they place the traction of"
                    + " --muscle-load pressure or paper-nodes");
        }
        if (rings != null && rings < 4) {
            throw new IllegalArgumentException("--rings/--resolution (rings per face of the generated dome) must be 4"
                    + " or more, got " + rings);
        }
        if (thicknessMm != null && !(thicknessMm > 0 && Double.isFinite(thicknessMm))) {
            throw new IllegalArgumentException("--thickness must be a finite number of mm > 0, got " + thicknessMm);
        }
        DiaphragmSpec.Mesh m = base.mesh();
        MeshCleaner.Options c = m.cleaning();
        m = m.withRings(rings != null ? rings : defaultRings)
                .withCleaning(new MeshCleaner.Options(weldMm == null ? c.weldToleranceM() : weldMm * 1e-3,
                        minPieceFraction == null ? c.minComponentFraction() : minPieceFraction))
                .withOffsetThickness(thicknessMm == null ? m.offsetThicknessM() : thicknessMm * 1e-3)
                .withLabels(labels);
        Path file = mesh != null ? mesh : defaultMesh;
        if (file != null) {
            m = m.withFile(file, MeshUnits.parse(units == null ? "mm" : units));
        } else if (units != null) {
            MeshUnits.parse(units); // validated even when unused
        }
        DiaphragmSpec.Breathing br = base.breathing();
        if (abdominalPressurePa != null) {
            try {
                br = br.withAbdominalPressure(abdominalPressurePa);
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException("--abdominal-pressure: " + e.getMessage(), e);
            }
        }
        br = new DiaphragmSpec.Breathing(periodS == null ? br.periodS() : periodS,
                ieRatio == null ? br.expirationRatio() : ieRatio,
                ribAmplitude == null ? br.ribAmplitude() : ribAmplitude, musclePa, br.abdominalPressurePa(),
                br.pauseShare());
        if (pauseShare != null) {
            try {
                br = br.withPauseShare(pauseShare);
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException("--expiratory-pause: " + e.getMessage(), e);
            }
        }
        DiaphragmSpec.Cage cageSpec;
        try {
            cageSpec = new DiaphragmSpec.Cage(boxes, thorax, contact == null ? base.cage().contact() : contact,
                    contactPaPerM == null ? base.cage().contactStiffnessPaPerM() : contactPaPerM,
                    liverPaPerM == null ? base.cage().liverSupportPaPerM() : liverPaPerM, cageSurfaces(),
                    appositionPa == null ? base.cage().appositionPressurePa() : appositionPa);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(appositionPa != null && e.getMessage().contains("apposition")
                    ? "--apposition-pressure: " + e.getMessage() : e.getMessage(), e);
        }
        return new DiaphragmSpec(m, p, b, br, cageSpec, actionLines,
                tendonRule == null ? base.tendonRule() : tendonRule);
    }

    /** Whether the bones are surfaces ({@code --thorax} or {@code --cage surfaces}): contact is on the table. */
    public boolean boneSurfaces() {
        return thorax != null || cageSurfaces();
    }

    /**
     * Whether {@code --cage surfaces} was given; refuses a value that is neither segments nor surfaces, and
     * segments with a thorax (whose bones are surfaces).
     */
    boolean cageSurfaces() {
        if (cage == null) {
            return DiaphragmSpec.Cage.defaults().surfaces();
        }
        if (!cage.equals("segments") && !cage.equals("surfaces")) {
            throw new IllegalArgumentException("--cage must be segments or surfaces, got '" + cage + "'");
        }
        if (cage.equals("segments") && thorax != null) {
            throw new IllegalArgumentException("--cage segments: a thorax (--thorax " + thorax + ") has bone surfaces,"
                    + " not segments; leave out --cage or give --cage surfaces");
        }
        return cage.equals("surfaces");
    }

    /** Whether {@code --model paper} was given; refuses a model that is neither default nor paper. */
    public boolean paperModel() {
        if (model != null && !model.equals("paper") && !model.equals("default")) {
            throw new IllegalArgumentException("--model must be default or paper, got '" + model + "'");
        }
        return "paper".equals(model);
    }

    private static Vec3 vector(String option, double[] v, double scale) {
        if (v.length != 3) {
            throw new IllegalArgumentException(option + " needs three numbers X,Y,Z, got " + v.length);
        }
        if (v[0] == 0 && v[1] == 0 && v[2] == 0 && option.equals("--tendon-normal")) {
            throw new IllegalArgumentException(option + " must not be the zero vector");
        }
        return new Vec3(scale * v[0], scale * v[1], scale * v[2]);
    }
}
