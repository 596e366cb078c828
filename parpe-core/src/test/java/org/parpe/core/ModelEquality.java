package org.parpe.core;

import java.lang.reflect.RecordComponent;
import java.util.List;
import java.util.Map;
import org.parpe.core.diag.SourcePos;

/** Compares models field by field, ignoring source positions and file names; names the first difference. */
final class ModelEquality {
    private ModelEquality() {
    }

    /** {@code null} when equal, else the path of the first difference. */
    static String diff(Object a, Object b, String path) {
        if (a == null || b == null) {
            return a == b ? null : path + ": " + a + " vs " + b;
        }
        if (a instanceof SourcePos) {
            return null;
        }
        if (a.getClass() != b.getClass()) {
            return path + ": " + a.getClass().getSimpleName() + " vs " + b.getClass().getSimpleName();
        }
        if (a instanceof Record) {
            for (RecordComponent c : a.getClass().getRecordComponents()) {
                if (c.getName().equals("file")) {
                    continue;
                }
                try {
                    String d = diff(c.getAccessor().invoke(a), c.getAccessor().invoke(b), path + "." + c.getName());
                    if (d != null) {
                        return d;
                    }
                } catch (ReflectiveOperationException e) {
                    throw new IllegalStateException(e);
                }
            }
            return null;
        }
        if (a instanceof List) {
            List<?> x = (List<?>) a;
            List<?> y = (List<?>) b;
            if (x.size() != y.size()) {
                return path + ": " + x.size() + " items vs " + y.size();
            }
            for (int i = 0; i < x.size(); i++) {
                String d = diff(x.get(i), y.get(i), path + "[" + i + "]");
                if (d != null) {
                    return d;
                }
            }
            return null;
        }
        if (a instanceof Map) {
            Map<?, ?> x = (Map<?, ?>) a;
            Map<?, ?> y = (Map<?, ?>) b;
            if (!x.keySet().equals(y.keySet())) {
                return path + ": keys " + x.keySet() + " vs " + y.keySet();
            }
            for (Object k : x.keySet()) {
                String d = diff(x.get(k), y.get(k), path + "{" + k + "}");
                if (d != null) {
                    return d;
                }
            }
            return null;
        }
        return a.equals(b) ? null : path + ": " + a + " vs " + b;
    }
}
