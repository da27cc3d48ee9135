/**
 * Rigid bodies of scene files: built-in surfaces as signed distances (box, sphere, plane) and motions under a time
 * law (translation, rotation). They serve contact, attachment and sliding through {@link org.tensim.model.ContactBody}.
 */
package org.tensim.scene.rigid;
