package org.tensim.tuning;

import org.tensim.scene.diaphragm.BoundaryConditions;
import org.tensim.scene.diaphragm.TendonRule;
import org.tensim.scene.shell.TissueModel;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/**
 * The model choices' names as options take them ({@code paper-nodes}, {@code paper-threshold}, {@code geodesic}),
 * read by the one parser of each ({@link BoundaryConditions#parse}, {@link TissueModel#parse}); an unknown name is
 * refused with the known ones.
 */
final class ModelNames {
    private ModelNames() {
    }

    static final class MuscleLoads implements ITypeConverter<BoundaryConditions.MuscleLoad> {
        @Override
        public BoundaryConditions.MuscleLoad convert(String name) {
            return parse(BoundaryConditions.MuscleLoad.class, name);
        }
    }

    static final class Attachments implements ITypeConverter<BoundaryConditions.Attachment> {
        @Override
        public BoundaryConditions.Attachment convert(String name) {
            return parse(BoundaryConditions.Attachment.class, name);
        }
    }

    static final class TendonRules implements ITypeConverter<TendonRule> {
        @Override
        public TendonRule convert(String name) {
            return parse(TendonRule.class, name);
        }
    }

    static final class TissueModels implements ITypeConverter<TissueModel> {
        @Override
        public TissueModel convert(String name) {
            try {
                return TissueModel.parse(name);
            } catch (IllegalArgumentException e) {
                throw new TypeConversionException(e.getMessage());
            }
        }
    }

    private static <E extends Enum<E>> E parse(Class<E> type, String name) {
        try {
            return BoundaryConditions.parse(type, name);
        } catch (IllegalArgumentException e) {
            throw new TypeConversionException(e.getMessage());
        }
    }
}
