package org.tensim.scene.file;

import java.util.ArrayList;
import java.util.List;

/**
 * {@code --set key.path=value}: replaces (or adds) one scalar of a scene's tree before it is read, e.g.
 * {@code --set bodies.mss.stiffness="200 N/m"}, {@code --set run.duration=1s},
 * {@code --set conditions[1].magnitude=300}. The value is read as the file's value would be, with the file's
 * units; its place in messages is the option itself. A path that leads nowhere is refused; a new key in an existing
 * map is checked like any key of the file (unknown keys get a "did you mean").
 */
public final class Overrides {
    private Overrides() {
    }

    /** Applies each {@code path=value} to {@code root} in order. */
    public static void apply(SceneNode root, List<String> sets) {
        for (String s : sets) {
            apply(root, s);
        }
    }

    private static void apply(SceneNode root, String set) {
        String[] kv = split(set);
        apply(root, "--set " + set, kv[0], kv[1]);
    }

    /** {@code path=value} as {path, value}; refused unless there is a key before the '='. */
    static String[] split(String set) {
        int eq = set.indexOf('=');
        if (eq <= 0) {
            throw new SceneException("--set " + set + ": expected key.path=value or NAME=value (a parameter of the"
                    + " file), e.g. run.duration=\"1 s\"");
        }
        return new String[] {set.substring(0, eq).strip(), set.substring(eq + 1).strip()};
    }

    /**
     * The node at a key path of the tree, or null when the path leads nowhere (its last key absent); refused when
     * it cannot be a path of this tree. {@code where} names the path's origin in messages.
     */
    static SceneNode find(SceneNode root, String path, String where) {
        SceneNode at = root;
        for (Object step : steps(path, where)) {
            if (step instanceof Integer k) {
                if (!at.isList() || k >= at.items().size()) {
                    return null;
                }
                at = at.items().get(k);
            } else {
                if (!at.isMap() || at.get((String) step) == null) {
                    return null;
                }
                at = at.get((String) step);
            }
        }
        return at;
    }

    /** Sets the scalar at {@code path} to {@code value}, the new node's place being {@code where}. */
    static void apply(SceneNode root, String where, String path, String value) {
        List<Object> steps = steps(path, where);
        SceneNode at = root;
        String walked = "";
        for (int i = 0; i < steps.size(); i++) {
            Object step = steps.get(i);
            boolean last = i == steps.size() - 1;
            String childPath = step instanceof Integer k ? walked + "[" + k + "]"
                    : SceneNode.child(walked, (String) step);
            SceneNode next;
            if (step instanceof Integer k) {
                if (!at.isList() || k >= at.items().size()) {
                    throw new SceneException(where + ": " + walked + " is not a list with an item " + k);
                }
                next = at.items().get(k);
            } else {
                if (!at.isMap()) {
                    throw new SceneException(where + ": " + (walked.isEmpty() ? "the top" : walked)
                            + " is not a map of keys");
                }
                next = at.get((String) step);
            }
            if (last) {
                if (next != null && !next.isScalar() && next.kind() != SceneNode.Kind.NULL) {
                    throw new SceneException(where + ": " + childPath + " is " + next.describe()
                            + ", not a single value; set one of its keys instead");
                }
                SceneNode v = SceneNode.scalar(SceneNode.Token.STRING, value, where, childPath);
                if (step instanceof Integer k) {
                    at.set(k, v);
                } else {
                    at.put((String) step, v);
                }
                return;
            }
            if (next == null) {
                throw new SceneException(where + ": the file has no " + childPath
                        + DidYouMean.suggest((String) step, at.entries().keySet()));
            }
            at = next;
            walked = childPath;
        }
    }

    /** "a.b[2].c" as ["a", "b", 2, "c"]. */
    static List<Object> steps(String path, String where) {
        List<Object> out = new ArrayList<>();
        for (String part : path.split("\\.", -1)) {
            String p = part;
            int br = p.indexOf('[');
            String key = br < 0 ? p : p.substring(0, br);
            if (key.isEmpty() && (br != 0 || out.isEmpty())) {
                throw new SceneException(where + ": '" + path + "' is not a key path (keys joined by '.', list"
                        + " items as [n])");
            }
            if (!key.isEmpty()) {
                out.add(key);
            }
            while (br >= 0) {
                int close = p.indexOf(']', br);
                try {
                    out.add(Integer.parseInt(p.substring(br + 1, close)));
                } catch (RuntimeException e) {
                    throw new SceneException(where + ": '" + path + "': a list item is written [n], n >= 0");
                }
                p = p.substring(close + 1);
                br = p.indexOf('[');
                if (!p.isEmpty() && br != 0) {
                    throw new SceneException(where + ": '" + path + "' is not a key path");
                }
            }
        }
        return out;
    }
}
