// A stand-in for the few types of Unity's Input System package (com.unity.inputsystem) that the
// samples read, following its documented signatures: Mouse.current, its buttons' wasPressedThisFrame
// and position.ReadValue(). The tests set them as a frame's input.
namespace UnityEngine.InputSystem
{
    public class Mouse
    {
        /// <summary>The mouse; null when none is connected.</summary>
        public static Mouse current { get; set; }

        public Controls.ButtonControl leftButton { get; } = new Controls.ButtonControl();
        public Controls.ButtonControl rightButton { get; } = new Controls.ButtonControl();
        public Controls.Vector2Control position { get; } = new Controls.Vector2Control();
    }
}

namespace UnityEngine.InputSystem.Controls
{
    public class ButtonControl
    {
        public bool wasPressedThisFrame { get; set; }
    }

    public class Vector2Control
    {
        public Vector2 Value;
        public Vector2 ReadValue() { return Value; }
    }
}
