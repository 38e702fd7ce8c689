// ros2_definitions.mjs - ros2msg schema text to the message definitions that
// @foxglove/rosmsg2-serialization's MessageReader takes; shared by read_mcap.mjs and
// foxglove_client.mjs.
import { parse as parseMessageDefinition } from "@foxglove/rosmsg";

/**
 * Parses ros2msg schema text. @foxglove/rosmsg turns builtin_interfaces/Time and Duration into
 * the primitive types "time"/"duration", which rosmsg2-serialization 2.x decodes as ROS 1 style
 * {sec, nsec}; model them as plain {int32 sec, uint32 nanosec} structs instead (same CDR layout)
 * so decoded messages carry the ROS 2 field names.
 */
export function ros2Definitions(text) {
  const definitions = parseMessageDefinition(text, { ros2: true });
  for (const { definitions: fields } of definitions) {
    for (const field of fields) {
      if (field.type === "time" || field.type === "duration") {
        field.type = field.type === "time" ? "builtin_interfaces/msg/Time" : "builtin_interfaces/msg/Duration";
        field.isComplex = true;
      }
    }
  }
  const secNanosec = [
    { name: "sec", type: "int32", isComplex: false, isArray: false },
    { name: "nanosec", type: "uint32", isComplex: false, isArray: false },
  ];
  definitions.push(
    { name: "builtin_interfaces/msg/Time", definitions: secNanosec },
    { name: "builtin_interfaces/msg/Duration", definitions: secNanosec },
  );
  return definitions;
}
